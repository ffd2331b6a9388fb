; thumbnail begin 96x96 2132
; iVBORw0KGgoAAAANSUhEUgAAAGAAAABgCAIAAABt+uBvAAAACXBIWXMAAA7EAAAOxAGVKw4bAAAF8U
; lEQVR4nO2cz2/bZBjHv69/JCkdLRkd24SSKa20LUhbD/S0gYNUeuK07jSu25+R7NDsxD+BhAQ3riBt
; Y8heKi7AZSBAlZItaBPraMPaJU3qXxzsJk6c5E3s12kjvR9Fkf3Gft/X3zzPN49du+Tbsg3OYCRy3D
; M44UiEKzQUHkEUhOOewElHIuAmPQyeYhS4SVPgHkSBpxgFLhAF7kEUuAdR4ClGgReKFLgHUeAeRIF7
; EAUuEAXuQRS4B1HgKUaBC0SBexAFCbySHgpPMQpcIArMPGhmc2Nmc0NP5Yx0znln0+9xQ7TnRvheHH
; V6GvVUDsDB9bsAplcv8jicQIl+0vTFmE69SCmEQInNjcRo6vgxUjkjnTNOfDKSzRdBBIqXgkvjx9Go
; dSKDK5BAT1Xy1aooQCIQBUisz+dOlF7BLrnaAEwLJgATAEQBAOIiAAZ6SVUVgFRddVaNdM5MKUY6Zx
; 6HWOSnF3qA3ewNecin7eACC728mG5wFdrLUROwUBwedf7gYpWMYlUF8FZVdQdK5wAc3HoYtt/BSIi4
; lDYtAFElY/lXdWsHyudh+xnCsAiSSxuxUtH5lvSP2ES1o1fDclfDOP3Wv9jaARDtV9xfILm0IZeKzr
; IT1eI3nai20sqhABwdbRiCOX1bGoeJCiRUVblUFI6S3I9YVcWqKssAYDjpY6FlMpiKP7jg02unga0d
; 7Da6doxWIG/30uNO4Iy0swAAlV0kZMwnGM/Mr1e9hZ+f99s0SoXcCBKqauzrT8fduR3qV851Guv7mH
; 2b0ew8mBa26/0/mkSK6WW12RrDMvuG+t4etv6CSCASV6O2WGfPA8DcPMDCuXqIWiC7PcaIltnjkV50
; G7oNAM3XACAT7O1BJCjvI5XC7IK7mWNejnOF1yvS+y8G1kF9LXOgC/h3tzvvS2ksXegetbvINiyYFg
; w7qFgT8CAqztQHucAgkvNYuoDT87RJCJAExAEAhoXtOk7FxhhlEh4UxRj+wBmFyi62612uT+UYCsVx
; kT8pyAmIT1T8qQGYm8PKlbE7aVvbuBXDROqgcIOIGSWWzckLCr5fc1oaOhCiOB6PCXjQiEMM+m4JQI
; DTV3PJqwoA86nmtI9SHAeW5tqyu3C2XDxVU98kcwDqSaWeZHkZhE2KkSOJV754CMCsqI0v1/yb+fV6
; 8k9vMUXF0eX6sqepXAQwW9PaDfWksr1YYKKUQDyHFwbieY2IaY39u35tGdeXu9Xpx2xNy/yy9l65SL
; onFuAlsJeHSYcDOD83xsazNTWsPKRzTTpUMUq6y9mQ+kgZZfZWAUDrxyIAo9LJHWsf0IFh13tdXr/G
; 73/jnZWwRTaDOujijfxCVvG2hA8gOaMAkDMPnFVHo7N/qO9Cw38aEsAMQACxd0eriTf7qB+i8gxIMZ
; hJKJO+eCN/ab3gb3cOLww9s3I6PJdRyHdrAKADNiB5csEEWoCOwybqDbx807+fALh10MxqQV7MATh4
; 1BvVg7i43l8dNlCPzAZsgAA2YLkn2H06Ca1QJ4LcqL7tRrVe0YyKqlc0v1iXIpUGADuXjzDFYhkldp
; QpekUDcPCoKDdx6ZpyOXp12FZnYRjJgxylYrcf0E7LmXGCIojBLJhyeT3PKkJtFtfRorrLVc4o+ghO
; 72Uhq2RvFnoqhh7GmiwhCH90UT0vlrxz/7CiAaj/cA9HLjaE7Ho+ezMPgO1dt+GPLsKbOOMZBUD8zn
; 1n1avXoUev7Hr+zAfKmaGBE5hp8iDX6T16HZa1bBPvf5af2BwCcGx32scXlfiiEsEf0Lpg4kHTxHgm
; zSLFOteDpuJVXxkjH0+v5hkM+nS3GVrliZJ4qc3/dg8CEjXNfdzNORczAB3NJmoN7H+Yj3/MxtrIs9
; qUCdQm/kpzUijxSoMFWGieUVrnGP8akurUCjQZpsykJw9/XowCf+KQAk8xClwgCvy5eQrcgyjwFKPA
; BaLAPYgC/xddFLhJU+AeRIF7EAUeQRS4B1HgEUSBexAFHkEUuAdR4JU0Be5BFLgHUeAeRIFHEIX/Aa
; Kb8zPLBybxAAAAAElFTkSuQmCC
; thumbnail end
; thumbnail begin 300x300 5384
; iVBORw0KGgoAAAANSUhEUgAAASwAAAEsCAIAAAD2HxkiAAAACXBIWXMAAA7EAAAOxAGVKw4bAAAPd0
; lEQVR4nO3d3W9b933H8Q9F0pIt24oSN06XUjYVzLZ6YRcrBgxJSqJIMgy7Wpy/YG3/DKkXkq/6X6wt
; drer3hR2t4CMjW1Ac+MA2zADkiKjziw/yI0iWRJ5yF0cUqZ1+MxDfs/5nfcLgkH6QT6yzsff7+/hnJ
; P6l/W6ANiZsj4AIOkyKesjABKOSggYI4SAMUIIGGNMCBjLiBQCpmhHAWOEEDBGCAFjTMwAxqiEgDFC
; CBgjhICxTEpcygRYohICxgghYIwQAsZYJwSMsYEbMEY7ChgjhIAxxoSAMSohYIwQAsYIIWCMMSFgjE
; oIGCOEgDFCCBhjTAgYoxICxtjADRijEgLGCCFgjIkZwBiVEDBGCAFjhBAwxpgQMEYlBIwRQsAYIQSM
; MSYEjGXEU5kAU2zgBowxJgSMMSYEjFEJAWOEEDBGCAFjjAkBY1RCwBghBIwRQsAYY0LAGJUQMEYIAW
; Ns4AaMMSYEjNGOAsYIIWCMEALGCCFgjIkZwBiVEDBGCAFjhBAwxpgQMEYlBIwRQsAYG7gBY4wJAWO0
; o4AxnsoEGKMSAsYYEwLGqISAMUIIGCOEgDHGhIAxKiFgjBACxpIVwuzDUvZhyfoogNckaAP36XurZ+
; 6t+q8ruaKklx/8UlJloWh5WEi8VPlPVetjGLvT91ZPN+PXVmsmq2QSk+V+CHsmMKiSK1YXiv6PYzoq
; 4JjLIRwifkEUSYybsyEMJYFBx0VSZBIhSX3hXAhnxhO/oGquKKmyUKzSuGIEToUws1U6fW81Y7QIUa
; VxxVDcCeHECmCfqrmiXyRFJtGVCyGMWvyCaFzRRepuzEM4c291JtoJDPIzeUDjCkmxDmEc49eWXx5p
; XBMrriF0JoEnHEeRxjU54hdCV+PXFo1rEqTuPYpNCDNbpel7q5mt5F4G4VdIb4HG1SmxCeH03QQVwH
; 74IfQzSSBjLSYh3Cylfv1RekqSptOSlEnWhZC9+Tk8pHGNoYz1AQzAq0nSfq3xNj2lTErpKQIpSX6X
; ntn6yH9L4xojMb7Rk1eTJ8mTJIrkCZmtUmarpHtSM4RerlhdaMQSkRKnSthFsEiKTDY1i2RpuiWTfu
; NKJqPAkRCeQOPaRbBx9ZprkmTSRFyeyjTSQdK4duE3rtOvNa4FGtdJSv37o4r1MfRhs1T/9cfj+MTH
; RVJkMsBrNK4rokiOk5vtaP+CRZLG9Vh6qyTpTHN3hLdQrOYKHo1r2JJeCbugce2isfiRK3g0riMjhP
; 1idqcLGtdRJL0d7R+zO13QuI4i9R/fxKAS1jdL9X8yroRdkMlOHjzV0Ycrl/7hl9YHEmnxqISpy8Uo
; L6SwLNnWg6d68EyXrA8j+uIRwnihcfXjhz4RwvFK4H46Ejio8W7gzt5dTW+VKx8yadbgduPaKX7xvU
; hgMsZVCbN3V0/dXfNfp//51aSZt1CoMWnW5FLjSgEc2lhC2JrAVumtUnqrJK2pGUKK5LH4Nq7Eb0Qh
; h7BT/IL8laXWIiky2SIWjeuzfT14puf71scRc6GNCae2Stm7a+lh78IUzGRtoeAtFGsEUlIkG9c+C2
; CKMWEv4VTC7N3VbH8FsE9+45ptaVzrU1KzPiSceeNK/xmuUUMYevyC/CI5m228rdYk6dCTyKSkiTeu
; JDB0I4VwAgkMyrx+7V+1Jq+map1ANoyvcSV+YzLkmDBjEb+2MlPKTGlaEkUyoFOR1OCZHCWBjAm7yw
; zxL5T5IioJPKG1SD54qovnbA8ncoa7gnnUAsjMTC+DtaORjV+r45OGEHbhF8mejSst6AT0G8KprVL2
; i7WpyD8HgpNmOMHGde9Qf/yT4RElSF9jwswXq5n4FECMzqs1htajoxvtqUcljEX8RAIRZ91CGIsEjh
; i/x4+0950kXfy+JM0yjMTEtQ/h1FZp6jcfR2qbYtCIGxcfP9L2N6/eru82Xsye0+xZnT1HIDEh7ceE
; lfWSV5Gium9YYRTA1gS22tvV3m7jV/0c7u02XlAth8OYsLseY8L47hvu5Ntvtf6/kpTu49TY233tRW
; u1FJlESAZYJ4zCxTWjT8B8u6uDmtQM4ZSUTvUVyFbBTLZ2sNNpTWfYT4d+Df9AmAkXydDnP726JHlS
; pS41M5lNvXrdv+MOdu68cjlNz0nsp3tNlO+VZ6/9mHDQJn7cF9dMYAWikcnm2ZJODVwkczkt5Nr/Uq
; dN50pAJlkn7Gkst7cIsXG1WgD06gMUyVxOc+c1N9fvJ6dIotUwG7gHNVzj+mxfz/cjsQQfLJJqyWSX
; AtiPYJGUe5mkFHY16fuO9tm4RnkHzHEm31vQe2HfX9q9qyXnlwrWhxB1xjf/bc2kH8i9Q63vxODeQe
; NIYBCNaxKM9+a/A/GaJ1nEEziZ+AXFtHFlYqYnboM/GKsEBrnXuCYWIexXdOLXlt+4frev7T29e976
; aDCIiG0JjaqIJ9D34Kn+82HUm3kEhbNY77C4xC+yk8nidOqFdrSj+Tm9d0lv9r0EbyXiCURPhLA9Ci
; AmxuUQTl0u1DbLJ37yfK8rj2IRP5FAh0RonTB0p//xD5K8zZK3Ua5tliR5gUyecCmnSyPsQZuMeMWP
; dcKeXK6EvvTlYvpyUVqR5G2WXt4v63863jhndlb7Tt9SABHUYQO3G/93Bb6KdL6Y3m33OwPcu6WAJT
; dOp7FxvxKOLsQnOgwtxglELy6vE47pSxvuiQ5Di3v8GBP2RCUcSZ9PdBiO7cOo/3xg8/cmUOJCOH+9
; OH+9sHO/xzTpcBy4pcDocu8od/HV2x/tr+nLkzNh380XJe3NNy413JtP9EPRExdCST/+1R8k7dwvSV
; r/7Zqk8WVyiCL54KmevYzTFtD3b0jSwkXl3mn3yztt/m1nAz/pB/Lx4oqSl0mX1wm7f2lvXi9KevNX
; je/3zv3S8/tl/XFct/134JYCrfxy98GN0D6hH8vFLz/x3+7NF7YXVxKSxiRWwrbmrxfnrxf3j0o9F/
; RDEd9Hkb1/o3PRC8/sTjn/5SeSthdX9uYLbqeREEZCiI8iG5/3b4RZ+vr09vqapO3Fle3FlUn/3ZMS
; sf0giCqTBB57e30t/+XHsztRf0btcAgherNNoM9vUJ3MYeIW6zGo3Dv2CTw2u1Ped258SCVEDx9ctz
; 6CFm+vr7lXDNtv4E7nC/p84scSuiFKIdUz+pzbCDf8U5niwOEvbXKOXlofQRtOfWenUs3/WU58OKDT
; l9b9wwGZfJh3nj/aCfGTjWrza+28GPI7G9kP1gldk8kXZn92R1J1o1zdaOw9qG6MtAPBe6L098I5vF
; F8vaXNLUX+zlsDI4TOyuQLxyXRD6GfySECWT+UnktnpVMhH2T/th7q4UOzv32snA3hX366bH0IEeKn
; 8UQmDz9fU/9F8kh6IZ2VzozrIDvxs+dqAuXqOuGVT5ev3HR2l1NPPb992XxBUjZ/x3/rN67VdkXyyq
; fLF7JlPW3+/L70UspKZybxH/j/PdLOC734s+otEzHODN2PuVYJEx6/4QQb14PP1zIvdOVy4crNFf3u
; k5N/oCrtShkpJc2EfxJ9+0ReTY+/0UFVB9WQP3kERS6EczPD/1kSODo/jWfzd37Y87dWpZS0L6WkrC
; QpLaUlDbgH5Ej1Q9XqqtW0/1zVmg4qOor8dvYQRS6EwyF+xjwpJdWayfT5Uaw3V/XqLW/r0pFUk+qS
; J9VUr6mapOC1cmFMeOXT5asksEVUvn3+1ZLHIay15HC0hyhG5QsMSbwrIfGDA9qHMJMvnPvZHUkvB5
; rFnqC3lgpvXSuQQPfUnNqR1pcOd+CWMosFSecWX81iVzZK1Y1hlnpDd+UmBbCr6LRrwUSFkrHofIFh
; 6PdGT9l8Iducxa5slCW9/DeDIvnWUuHqzZULS2HujXSPW6foSawTSsdLvT9vFMmJZfIqBRAuCmFiJp
; jJ6kapEmrjSvzgsPBnR/3G9bSkkIokCYTbxnvz31P5gqRTLUXSn92p9BfIqzeXr002fg4MNkIfMkXt
; 34Qx4Ug6ze60zeTkEwiYMFusD44k/SIp6epfFYgfkiMqO2Zai+R520MBJotbHgLGXH4qUzJdWCq4/T
; 11b2KGSuiUa8xmxVBUxoQYEfGLr44buBEXF5YK1z5L0n5a5/pRxoTxdu3m8tJniSuAjp20tKNxdWGp
; sJSoAuguQhhLySyAriKEr3njF3cqG+Wj9VKl7w2uE5bk+NUdveg+k3LrATejO5X/yan8T/zXRxtlSX
; v/eksdNrhO2NLN5aXPlh17JtGgUqo7dtJSCbtpXAXyi9v+26ONcmW9fGRRJJvxg4MI4QBO5Qun8oVZ
; SZMtkiTQbYRwSMEiqTFkkvglAeuE4ZjOFyRNt2TyaL1c2SgfjRDIpZvLP4xAAsM/Q0Yb0Dm3Vk8lHA
; +/cfVftxbJPjMZkfhhMgjh2AUb1+5FkgQmDSGctE5FUv9dTmL8Oremrq4KBmVSjvXXsTK9WJA0vXhb
; 0pvWB2Oo/7jV60ql5NhJy/WEgDFCCBgjhIgJd4eIrBMifhw7aamEgDFCCBgjhOjBe3e0i/dDHcudXi
; ycWXTtZgKEED3s//Xy0V9E5bx/4yMHNzMwMYPenvz97Yu//9uZbePLmi/+/PZ0Pir/HYSISoi+PP67
; 2y9umFWhcz9d/sHagZMJlJTafH5gfQyIk7mvbr3x1a3GKkFKmmr5UYELjeotY8Ja863/UXv1UaupVl
; PF05H/UdWRp4OKDj1lP1yu13Xupw52occIIYYxs12e++rWzJPy+ELo/c1y9kOXs3cs9fUOIcTwprfL
; c/91SynNPC1Lo4Zw98fLXk3Vdwv1H7jZebZFCBGa6SdlqZHG6afNWZy6Zp6UpWYIpYMLBT+Hh283Xh
; xcLBx+P0GpO4EQAsaYHQWMsU4IGKMSAsYIIWCMEALGGBMCxjIu3zYAiAPaUcAYIQSMMSYEjFEJAWMZ
; 124fB8QNlRAwxpgQMEYlBIwRQsAYIQSMEULAGBMzgDEqIWCMEALGCCFgjDEhYIxKCBhjAzdgjEoIGG
; NMCBijEgLGCCFgjBACxhgTAsaohIAxQggYI4SAMcaEgDEqIWCMpzIBxtjADRhjTAgYY0wIGCOEgDFC
; CBhjTAgYoxICxgghYIwQAsYIIWCMiRnAGJUQMEYIAWNs4AaMMSYEjNGOAsYIIWCMEALGGBMCxqiEgD
; FCCBgjhIAxxoSAMSohYIwQAsYIIWAsk2JQCJiiEgLGCCFgjKcyAcaohIAxFusBY1RCwBghBIwRQsAY
; Y0LAGJUQMEYIAWOEEDDGBm7AGJUQMEYIAWOEEDDGOiFgjEoIGPt/KFILcpRiOKkAAAAASUVORK5CYI
; I=
; thumbnail end
; G-Code generated by Simplify3D(R) Version 5.1.2
; Mar 24, 2024 at 10:10:34 AM
; Settings Summary
;   processName,Process 1
;   autoConfigureMaterial,ABS
;   autoConfigureQuality,High
;   targetModels,cube_1
;   profileName,Creality K1 Max
;   profileVersion,2024-03-24 00:18:47
;   app,S3D-Software 5.1.2
;   technology,fff
;   baseProfile,
;   extruder,Primary Extruder
;   toolheadNumber,0
;   nozzleDiameter,0.40000
;   extrusionMultiplier,0.95000
;   extrusionWidthMode,manual
;   extrusionWidth,0.40000
;   useRetraction,1
;   retractDistance,0.50000
;   extraRestartDistance,0.00000
;   retractVerticalLift,0.00000
;   retractSpeed,2400.00000
;   useCoasting,0
;   coastingDistance,0.20000
;   useWiping,0
;   wipingDistance,5.00000
;   speedMaxFlowRate,1000.00000
;   toolheadOffsetX,0.00000
;   toolheadOffsetY,0.00000
;   filamentDiameter,1.75000
;   filamentPricePerKilogram,20.00000
;   filamentDensity,1.25000
;   primaryExtruder,Primary Extruder
;   layerHeight,0.10000
;   topSolidLayers,6
;   bottomSolidLayers,6
;   outlinePerimeters,4
;   useVaseMode,0
;   useAdaptiveLayerHeights,0
;   minAdaptiveLayerHeight,0.10000
;   maxAdaptiveLayerHeight,0.30000
;   adaptiveSmoothingLevel,5
;   horizontalOuterCompensation,0.00000
;   horizontalInnerCompensation,0.00000
;   firstLayerUnits,absolute
;   firstLayerHeightPercentage,150
;   firstLayerWidthPercentage,100
;   firstLayerSpeedPercentage,15
;   firstLayerHeightAbsolute,0.30000
;   firstLayerWidthAbsolute,0.40000
;   firstLayerSpeedAbsolute,1500.00000
;   startPointStrategy,closest
;   alignStartPointsX,0.00000
;   alignStartPointsY,0.00000
;   restrictStartPoints,1
;   perimeterPrintingOrder,inside_out
;   islandPrintingOrder,closest
;   printInfillBeforePerimeters,0
;   useSkirt,0
;   skirtExtruder,Primary Extruder
;   skirtLayers,1
;   skirtOffset,0.10000
;   skirtOutlines,3
;   useRaft,0
;   raftExtruder,Primary Extruder
;   raftBaseLayers,2
;   raftTopLayers,3
;   raftOffset,3.00000
;   raftSeparationDistance,0.14000
;   raftSpeedUnits,percentage
;   raftSpeedPercentage,30
;   raftSpeedAbsolute,600.00000
;   usePrimePillar,0
;   primePillarExtruder,All Extruders
;   primePillarWidth,12.00000
;   primePillarLocation,north_west
;   primePillarSpeedPercentage,100
;   primePillarInfillPercentage,100
;   autoStopPrimePillar,1
;   primePillarLayersAfterAutoStop,0
;   useOozeShield,0
;   oozeShieldExtruder,All Extruders
;   oozeShieldOffset,2.00000
;   oozeShieldOutlines,1
;   oozeShieldSidewallShape,waterfall
;   oozeShieldSidewallAngle,30
;   oozeShieldSpeedPercentage,100
;   autoStopOozeShield,1
;   oozeShieldLayersAfterAutoStop,0
;   sparseInfillExtruder,Primary Extruder
;   sparseInfillPattern,rectilinear
;   sparseInfillRotation,0
;   sparseInfillPercentage,30
;   sparseInfillExtrusionWidthPercentage,100
;   sparseInfillCombinedLayers,1
;   denseInfillLayers,0
;   denseInfillPercentage,50
;   infillOutlineOverlapPercentage,30
;   minInfillLength,5.00000
;   externalInfillPattern,rectilinear
;   externalInfillRotation,0
;   solidInfillThresholdArea,25.00000
;   solidInfillExtraExpansion,0.00000
;   useMonotonic,0
;   useDiaphragm,0
;   diaphragmSolidLayers,3
;   diaphragmSpacingLayers,20
;   topLayerExtraExpansion,1.00000
;   topLayerExtrusionModifier,100
;   overrideFanSpeedForTopLayer,0
;   topLayerFanSpeedPercentage,100
;   useIroning,0
;   ironingOutlineOffsetPercentage,50
;   ironingExtrusionWidthPercentage,25
;   ironingExtrusionModifier,15
;   ironingSpeedModifier,30
;   sparseSupportExtruder,Primary Extruder
;   sparseSupportInfillPattern,aligned
;   sparseSupportInfillRotation,0
;   sparseSupportInfillPercentage,40
;   sparseSupportOutlines,0
;   sparseSupportCombinedLayers,1
;   upperDenseSupportLayers,0
;   lowerDenseSupportLayers,0
;   denseSupportExtruder,Primary Extruder
;   denseSupportInfillPercentage,70
;   denseSupportExtraExpansion,0.00000
;   baseSupportLayers,1
;   supportInflationDistance,0.00000
;   supportHorizontalPartOffset,0.30000
;   supportUpperSeparationLayers,1
;   supportLowerSeparationLayers,1
;   temperatureController,Primary Extruder
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,extruder
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|260
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   temperatureController,Heated Build Platform
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,platform
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|110
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   fan,Cooling Fan
;   fanNumber,0
;   fanType,extruder
;   blipFanToFullPower,0
;   fanSetpoints,1|30
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,10.00000
;   maxQuickLayerFanSpeedPercentage,100
;   fan,Side Fan
;   fanNumber,2
;   fanType,environmental
;   blipFanToFullPower,0
;   fanSetpoints,1|0
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,15.00000
;   maxQuickLayerFanSpeedPercentage,100
;   defaultPrintSpeed,27000.00000
;   outerPerimeterSpeedPercentage,70
;   innerPerimeterSpeedPercentage,80
;   topLayerSpeedPercentage,50
;   solidInfillSpeedPercentage,80
;   sparseSupportSpeedPercentage,80
;   denseSupportSpeedPercentage,70
;   travelSpeedXY,18000.00000
;   travelSpeedZ,2400.00000
;   reduceSpeedForQuickLayers,1
;   speedMaxQuickLayerTime,5.00000
;   minQuickLayerSpeedPercentage,70
;   reduceSpeedForShortPerimeters,1
;   speedMaxShortPerimeterLength,20.00000
;   minShortPerimeterSpeedPercentage,70
;   reduceSpeedForMaxFlowRate,0
;   accelXY,20000.00000
;   accelZ,500.00000
;   accelE,5000.00000
;   jerkXY,600.00000
;   jerkZ,24.00000
;   jerkE,300.00000
;   exportFileFormat,gcode
;   useStickyCommands,1
;   use5D,1
;   relativeExtrusionDistances,0
;   allowExtruderAxisZeroing,1
;   independentExtruderAxes,0
;   includeM10123,0
;   includeThumbnailImages,1
;   thumbnailImageEncoding,standard
;   thumbnailImageSizes,300|300,96|96
;   x3gMachineProfile,r2
;   overrideStepsPerMillimeter,0
;   stepsPerMillimeterX,88.57319
;   stepsPerMillimeterY,88.57319
;   stepsPerMillimeterZ,400.00000
;   stepsPerMillimeterA,96.27520
;   stepsPerMillimeterB,96.27520
;   xyzFileFormatVersion,1
;   makerBotMachineProfile,replicator_5
;   makerBotModelExtruder,mk13
;   makerBotSupportExtruder,mk14_s
;   makerBotModelMaterial,pla
;   makerBotSupportMaterial,pva
;   globalOffsetX,0.00000
;   globalOffsetY,0.00000
;   globalOffsetZ,0.00000
;   applyToolheadOffsets,0
;   buildVolumeShape,rectangular
;   buildVolumeX,300.00000
;   buildVolumeY,300.00000
;   buildVolumeZ,300.00000
;   buildVolumeDiameter,200.00000
;   originOffsetX,0.00000
;   originOffsetY,0.00000
;   originOffsetZ,0.00000
;   homingDirectionX,min
;   homingDirectionY,min
;   homingDirectionZ,min
;   mirrorVisualX,0
;   mirrorVisualY,1
;   mirrorVisualZ,0
;   machineBackgroundModel,Creality_K1Max.stl
;   startingScript,";TIME:[total_print_time_sec].00|;Filament used:{EVAL ""[total_filament_used]/1000""}m|;Layer height: [current_layer_height]|START_PRINT EXTRUDER_TEMP=[extruder0_temperature] BED_TEMP=[platform0_temperature]|M106 S[fan_speed_pwm] P0|M141 S50"
;   preLayerChangeScript,
;   postLayerChangeScript,
;   preRetractionScript,
;   postRetractionScript,
;   preToolChangeScript,
;   postToolChangeScript,
;   processChangeScript,
;   endingScript,END_PRINT|M106 S0 ; turn off cooling fan|
;   postProcessingScript,"C:\Users\Michael\git\preprocess_cancellation_MJ666\dist\preprocess_cancellation.exe ""[output_filepath]"""
;   useBridging,1
;   bridgingThresholdArea,50.00000
;   bridgingInfillExtraExpansion,0.00000
;   bridgingExtrusionModifier,100
;   bridgingSpeedModifier,100
;   overrideFanSpeedForBridging,1
;   bridgingFanSpeedPercentage,100
;   useFixedBridgingAngle,0
;   fixedBridgingAngle,0
;   applyBridgingToPerimeters,0
;   bridgingPerimeterExtraOverlap,0.00000
;   minBridgingPerimeterLength,10.00000
;   useToolChangeRetraction,1
;   toolChangeRetractDistance,12.00000
;   toolChangeExtraRestartDistance,-0.50000
;   toolChangeRetractSpeed,600.00000
;   toolChangePrimeOnFirstUse,0
;   toolChangeRetractAtEnd,0
;   externalThinWallType,perimeters_only
;   internalThinWallType,single_extrusions
;   thinWallAllowedOverlapPercentage,10
;   singleExtrusionMinLength,1.00000
;   singleExtrusionMinWidthPercentage,50
;   singleExtrusionMaxWidthPercentage,200
;   singleExtrusionEndpointExtensionDistance,0.20000
;   onlyRetractWhenCrossingOutlines,1
;   retractBetweenLayers,1
;   retractOnTopLayers,1
;   useRetractionMinTravel,0
;   retractionMinTravel,5.00000
;   useRetractionMinExtrusion,0
;   retractionMinExtrusion,3.00000
;   onlyVerticalLiftOnTopLayers,0
;   retractWhileWiping,0
;   wipingMode,outer_perimeter
;   avoidCrossingOutlines,0
;   maxMovementDetourFactor,3.00000
;   openLoopSlicingBehavior,heal
;   openLoopThickenWidth,0.50000
;   slicingRegionRepairMode,positive
;   processName,Process 2
;   autoConfigureMaterial,ABS
;   autoConfigureQuality,High
;   targetModels,cube_1(2)
;   profileName,Creality K1 Max
;   profileVersion,2024-03-24 00:57:34
;   app,S3D-Software 5.1.2
;   technology,fff
;   baseProfile,
;   extruder,Primary Extruder
;   toolheadNumber,0
;   nozzleDiameter,0.40000
;   extrusionMultiplier,0.95000
;   extrusionWidthMode,manual
;   extrusionWidth,0.40000
;   useRetraction,1
;   retractDistance,0.50000
;   extraRestartDistance,0.00000
;   retractVerticalLift,0.00000
;   retractSpeed,2400.00000
;   useCoasting,0
;   coastingDistance,0.20000
;   useWiping,0
;   wipingDistance,5.00000
;   speedMaxFlowRate,1000.00000
;   toolheadOffsetX,0.00000
;   toolheadOffsetY,0.00000
;   filamentDiameter,1.75000
;   filamentPricePerKilogram,20.00000
;   filamentDensity,1.25000
;   primaryExtruder,Primary Extruder
;   layerHeight,0.10000
;   topSolidLayers,6
;   bottomSolidLayers,6
;   outlinePerimeters,4
;   useVaseMode,0
;   useAdaptiveLayerHeights,0
;   minAdaptiveLayerHeight,0.10000
;   maxAdaptiveLayerHeight,0.30000
;   adaptiveSmoothingLevel,5
;   horizontalOuterCompensation,0.00000
;   horizontalInnerCompensation,0.00000
;   firstLayerUnits,absolute
;   firstLayerHeightPercentage,150
;   firstLayerWidthPercentage,100
;   firstLayerSpeedPercentage,15
;   firstLayerHeightAbsolute,0.30000
;   firstLayerWidthAbsolute,0.40000
;   firstLayerSpeedAbsolute,1500.00000
;   startPointStrategy,closest
;   alignStartPointsX,0.00000
;   alignStartPointsY,0.00000
;   restrictStartPoints,1
;   perimeterPrintingOrder,inside_out
;   islandPrintingOrder,closest
;   printInfillBeforePerimeters,0
;   useSkirt,0
;   skirtExtruder,Primary Extruder
;   skirtLayers,1
;   skirtOffset,0.10000
;   skirtOutlines,3
;   useRaft,0
;   raftExtruder,Primary Extruder
;   raftBaseLayers,2
;   raftTopLayers,3
;   raftOffset,3.00000
;   raftSeparationDistance,0.14000
;   raftSpeedUnits,percentage
;   raftSpeedPercentage,30
;   raftSpeedAbsolute,600.00000
;   usePrimePillar,0
;   primePillarExtruder,All Extruders
;   primePillarWidth,12.00000
;   primePillarLocation,north_west
;   primePillarSpeedPercentage,100
;   primePillarInfillPercentage,100
;   autoStopPrimePillar,1
;   primePillarLayersAfterAutoStop,0
;   useOozeShield,0
;   oozeShieldExtruder,All Extruders
;   oozeShieldOffset,2.00000
;   oozeShieldOutlines,1
;   oozeShieldSidewallShape,waterfall
;   oozeShieldSidewallAngle,30
;   oozeShieldSpeedPercentage,100
;   autoStopOozeShield,1
;   oozeShieldLayersAfterAutoStop,0
;   sparseInfillExtruder,Primary Extruder
;   sparseInfillPattern,rectilinear
;   sparseInfillRotation,0
;   sparseInfillPercentage,30
;   sparseInfillExtrusionWidthPercentage,100
;   sparseInfillCombinedLayers,1
;   denseInfillLayers,0
;   denseInfillPercentage,50
;   infillOutlineOverlapPercentage,30
;   minInfillLength,5.00000
;   externalInfillPattern,rectilinear
;   externalInfillRotation,0
;   solidInfillThresholdArea,25.00000
;   solidInfillExtraExpansion,0.00000
;   useMonotonic,0
;   useDiaphragm,0
;   diaphragmSolidLayers,3
;   diaphragmSpacingLayers,20
;   topLayerExtraExpansion,1.00000
;   topLayerExtrusionModifier,100
;   overrideFanSpeedForTopLayer,0
;   topLayerFanSpeedPercentage,100
;   useIroning,0
;   ironingOutlineOffsetPercentage,50
;   ironingExtrusionWidthPercentage,25
;   ironingExtrusionModifier,15
;   ironingSpeedModifier,30
;   sparseSupportExtruder,Primary Extruder
;   sparseSupportInfillPattern,aligned
;   sparseSupportInfillRotation,0
;   sparseSupportInfillPercentage,40
;   sparseSupportOutlines,0
;   sparseSupportCombinedLayers,1
;   upperDenseSupportLayers,0
;   lowerDenseSupportLayers,0
;   denseSupportExtruder,Primary Extruder
;   denseSupportInfillPercentage,70
;   denseSupportExtraExpansion,0.00000
;   baseSupportLayers,1
;   supportInflationDistance,0.00000
;   supportHorizontalPartOffset,0.30000
;   supportUpperSeparationLayers,1
;   supportLowerSeparationLayers,1
;   temperatureController,Primary Extruder
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,extruder
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|260
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   temperatureController,Heated Build Platform
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,platform
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|110
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   fan,Cooling Fan
;   fanNumber,0
;   fanType,extruder
;   blipFanToFullPower,0
;   fanSetpoints,1|30
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,10.00000
;   maxQuickLayerFanSpeedPercentage,100
;   fan,Side Fan
;   fanNumber,2
;   fanType,environmental
;   blipFanToFullPower,0
;   fanSetpoints,1|0
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,15.00000
;   maxQuickLayerFanSpeedPercentage,100
;   defaultPrintSpeed,27000.00000
;   outerPerimeterSpeedPercentage,70
;   innerPerimeterSpeedPercentage,80
;   topLayerSpeedPercentage,50
;   solidInfillSpeedPercentage,80
;   sparseSupportSpeedPercentage,80
;   denseSupportSpeedPercentage,70
;   travelSpeedXY,18000.00000
;   travelSpeedZ,2400.00000
;   reduceSpeedForQuickLayers,1
;   speedMaxQuickLayerTime,5.00000
;   minQuickLayerSpeedPercentage,70
;   reduceSpeedForShortPerimeters,1
;   speedMaxShortPerimeterLength,20.00000
;   minShortPerimeterSpeedPercentage,70
;   reduceSpeedForMaxFlowRate,0
;   accelXY,20000.00000
;   accelZ,500.00000
;   accelE,5000.00000
;   jerkXY,600.00000
;   jerkZ,24.00000
;   jerkE,300.00000
;   exportFileFormat,gcode
;   useStickyCommands,1
;   use5D,1
;   relativeExtrusionDistances,0
;   allowExtruderAxisZeroing,1
;   independentExtruderAxes,0
;   includeM10123,0
;   includeThumbnailImages,1
;   thumbnailImageEncoding,standard
;   thumbnailImageSizes,300|300,96|96
;   x3gMachineProfile,r2
;   overrideStepsPerMillimeter,0
;   stepsPerMillimeterX,88.57319
;   stepsPerMillimeterY,88.57319
;   stepsPerMillimeterZ,400.00000
;   stepsPerMillimeterA,96.27520
;   stepsPerMillimeterB,96.27520
;   xyzFileFormatVersion,1
;   makerBotMachineProfile,replicator_5
;   makerBotModelExtruder,mk13
;   makerBotSupportExtruder,mk14_s
;   makerBotModelMaterial,pla
;   makerBotSupportMaterial,pva
;   globalOffsetX,0.00000
;   globalOffsetY,0.00000
;   globalOffsetZ,0.00000
;   applyToolheadOffsets,0
;   buildVolumeShape,rectangular
;   buildVolumeX,300.00000
;   buildVolumeY,300.00000
;   buildVolumeZ,300.00000
;   buildVolumeDiameter,200.00000
;   originOffsetX,0.00000
;   originOffsetY,0.00000
;   originOffsetZ,0.00000
;   homingDirectionX,min
;   homingDirectionY,min
;   homingDirectionZ,min
;   mirrorVisualX,0
;   mirrorVisualY,1
;   mirrorVisualZ,0
;   machineBackgroundModel,Creality_K1Max.stl
;   startingScript,";TIME:[total_print_time_sec].00|;Filament used:{EVAL ""[total_filament_used]/1000""}m|;Layer height: [current_layer_height]|START_PRINT EXTRUDER_TEMP=[extruder0_temperature] BED_TEMP=[platform0_temperature]|M106 S[fan_speed_pwm] P0|M141 S50"
;   preLayerChangeScript,
;   postLayerChangeScript,
;   preRetractionScript,
;   postRetractionScript,
;   preToolChangeScript,
;   postToolChangeScript,
;   processChangeScript,
;   endingScript,END_PRINT|M106 S0 ; turn off cooling fan|
;   postProcessingScript,"C:\Users\Michael\git\preprocess_cancellation_MJ666\dist\preprocess_cancellation.exe ""[output_filepath]"""
;   useBridging,1
;   bridgingThresholdArea,50.00000
;   bridgingInfillExtraExpansion,0.00000
;   bridgingExtrusionModifier,100
;   bridgingSpeedModifier,100
;   overrideFanSpeedForBridging,1
;   bridgingFanSpeedPercentage,100
;   useFixedBridgingAngle,0
;   fixedBridgingAngle,0
;   applyBridgingToPerimeters,0
;   bridgingPerimeterExtraOverlap,0.00000
;   minBridgingPerimeterLength,10.00000
;   useToolChangeRetraction,1
;   toolChangeRetractDistance,12.00000
;   toolChangeExtraRestartDistance,-0.50000
;   toolChangeRetractSpeed,600.00000
;   toolChangePrimeOnFirstUse,0
;   toolChangeRetractAtEnd,0
;   externalThinWallType,perimeters_only
;   internalThinWallType,single_extrusions
;   thinWallAllowedOverlapPercentage,10
;   singleExtrusionMinLength,1.00000
;   singleExtrusionMinWidthPercentage,50
;   singleExtrusionMaxWidthPercentage,200
;   singleExtrusionEndpointExtensionDistance,0.20000
;   onlyRetractWhenCrossingOutlines,1
;   retractBetweenLayers,1
;   retractOnTopLayers,1
;   useRetractionMinTravel,0
;   retractionMinTravel,5.00000
;   useRetractionMinExtrusion,0
;   retractionMinExtrusion,3.00000
;   onlyVerticalLiftOnTopLayers,0
;   retractWhileWiping,0
;   wipingMode,outer_perimeter
;   avoidCrossingOutlines,0
;   maxMovementDetourFactor,3.00000
;   openLoopSlicingBehavior,heal
;   openLoopThickenWidth,0.50000
;   slicingRegionRepairMode,positive
;   processName,Process 3
;   autoConfigureMaterial,ABS
;   autoConfigureQuality,High
;   targetModels,union_3
;   profileName,Creality K1 Max
;   profileVersion,2024-03-24 00:57:34
;   app,S3D-Software 5.1.2
;   technology,fff
;   baseProfile,
;   extruder,Primary Extruder
;   toolheadNumber,0
;   nozzleDiameter,0.40000
;   extrusionMultiplier,0.95000
;   extrusionWidthMode,manual
;   extrusionWidth,0.40000
;   useRetraction,1
;   retractDistance,0.50000
;   extraRestartDistance,0.00000
;   retractVerticalLift,0.00000
;   retractSpeed,2400.00000
;   useCoasting,0
;   coastingDistance,0.20000
;   useWiping,0
;   wipingDistance,5.00000
;   speedMaxFlowRate,1000.00000
;   toolheadOffsetX,0.00000
;   toolheadOffsetY,0.00000
;   filamentDiameter,1.75000
;   filamentPricePerKilogram,20.00000
;   filamentDensity,1.25000
;   primaryExtruder,Primary Extruder
;   layerHeight,0.10000
;   topSolidLayers,6
;   bottomSolidLayers,6
;   outlinePerimeters,4
;   useVaseMode,0
;   useAdaptiveLayerHeights,0
;   minAdaptiveLayerHeight,0.10000
;   maxAdaptiveLayerHeight,0.30000
;   adaptiveSmoothingLevel,5
;   horizontalOuterCompensation,0.00000
;   horizontalInnerCompensation,0.00000
;   firstLayerUnits,absolute
;   firstLayerHeightPercentage,150
;   firstLayerWidthPercentage,100
;   firstLayerSpeedPercentage,15
;   firstLayerHeightAbsolute,0.30000
;   firstLayerWidthAbsolute,0.40000
;   firstLayerSpeedAbsolute,1500.00000
;   startPointStrategy,closest
;   alignStartPointsX,0.00000
;   alignStartPointsY,0.00000
;   restrictStartPoints,1
;   perimeterPrintingOrder,inside_out
;   islandPrintingOrder,closest
;   printInfillBeforePerimeters,0
;   useSkirt,0
;   skirtExtruder,Primary Extruder
;   skirtLayers,1
;   skirtOffset,0.10000
;   skirtOutlines,3
;   useRaft,0
;   raftExtruder,Primary Extruder
;   raftBaseLayers,2
;   raftTopLayers,3
;   raftOffset,3.00000
;   raftSeparationDistance,0.14000
;   raftSpeedUnits,percentage
;   raftSpeedPercentage,30
;   raftSpeedAbsolute,600.00000
;   usePrimePillar,0
;   primePillarExtruder,All Extruders
;   primePillarWidth,12.00000
;   primePillarLocation,north_west
;   primePillarSpeedPercentage,100
;   primePillarInfillPercentage,100
;   autoStopPrimePillar,1
;   primePillarLayersAfterAutoStop,0
;   useOozeShield,0
;   oozeShieldExtruder,All Extruders
;   oozeShieldOffset,2.00000
;   oozeShieldOutlines,1
;   oozeShieldSidewallShape,waterfall
;   oozeShieldSidewallAngle,30
;   oozeShieldSpeedPercentage,100
;   autoStopOozeShield,1
;   oozeShieldLayersAfterAutoStop,0
;   sparseInfillExtruder,Primary Extruder
;   sparseInfillPattern,rectilinear
;   sparseInfillRotation,0
;   sparseInfillPercentage,30
;   sparseInfillExtrusionWidthPercentage,100
;   sparseInfillCombinedLayers,1
;   denseInfillLayers,0
;   denseInfillPercentage,50
;   infillOutlineOverlapPercentage,30
;   minInfillLength,5.00000
;   externalInfillPattern,rectilinear
;   externalInfillRotation,0
;   solidInfillThresholdArea,25.00000
;   solidInfillExtraExpansion,0.00000
;   useMonotonic,0
;   useDiaphragm,0
;   diaphragmSolidLayers,3
;   diaphragmSpacingLayers,20
;   topLayerExtraExpansion,1.00000
;   topLayerExtrusionModifier,100
;   overrideFanSpeedForTopLayer,0
;   topLayerFanSpeedPercentage,100
;   useIroning,0
;   ironingOutlineOffsetPercentage,50
;   ironingExtrusionWidthPercentage,25
;   ironingExtrusionModifier,15
;   ironingSpeedModifier,30
;   sparseSupportExtruder,Primary Extruder
;   sparseSupportInfillPattern,aligned
;   sparseSupportInfillRotation,0
;   sparseSupportInfillPercentage,40
;   sparseSupportOutlines,0
;   sparseSupportCombinedLayers,1
;   upperDenseSupportLayers,0
;   lowerDenseSupportLayers,0
;   denseSupportExtruder,Primary Extruder
;   denseSupportInfillPercentage,70
;   denseSupportExtraExpansion,0.00000
;   baseSupportLayers,1
;   supportInflationDistance,0.00000
;   supportHorizontalPartOffset,0.30000
;   supportUpperSeparationLayers,1
;   supportLowerSeparationLayers,1
;   temperatureController,Primary Extruder
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,extruder
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|260
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   temperatureController,Heated Build Platform
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,platform
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|110
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   fan,Cooling Fan
;   fanNumber,0
;   fanType,extruder
;   blipFanToFullPower,0
;   fanSetpoints,1|30
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,10.00000
;   maxQuickLayerFanSpeedPercentage,100
;   fan,Side Fan
;   fanNumber,2
;   fanType,environmental
;   blipFanToFullPower,0
;   fanSetpoints,1|0
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,15.00000
;   maxQuickLayerFanSpeedPercentage,100
;   defaultPrintSpeed,27000.00000
;   outerPerimeterSpeedPercentage,70
;   innerPerimeterSpeedPercentage,80
;   topLayerSpeedPercentage,50
;   solidInfillSpeedPercentage,80
;   sparseSupportSpeedPercentage,80
;   denseSupportSpeedPercentage,70
;   travelSpeedXY,18000.00000
;   travelSpeedZ,2400.00000
;   reduceSpeedForQuickLayers,1
;   speedMaxQuickLayerTime,5.00000
;   minQuickLayerSpeedPercentage,70
;   reduceSpeedForShortPerimeters,1
;   speedMaxShortPerimeterLength,20.00000
;   minShortPerimeterSpeedPercentage,70
;   reduceSpeedForMaxFlowRate,0
;   accelXY,20000.00000
;   accelZ,500.00000
;   accelE,5000.00000
;   jerkXY,600.00000
;   jerkZ,24.00000
;   jerkE,300.00000
;   exportFileFormat,gcode
;   useStickyCommands,1
;   use5D,1
;   relativeExtrusionDistances,0
;   allowExtruderAxisZeroing,1
;   independentExtruderAxes,0
;   includeM10123,0
;   includeThumbnailImages,1
;   thumbnailImageEncoding,standard
;   thumbnailImageSizes,300|300,96|96
;   x3gMachineProfile,r2
;   overrideStepsPerMillimeter,0
;   stepsPerMillimeterX,88.57319
;   stepsPerMillimeterY,88.57319
;   stepsPerMillimeterZ,400.00000
;   stepsPerMillimeterA,96.27520
;   stepsPerMillimeterB,96.27520
;   xyzFileFormatVersion,1
;   makerBotMachineProfile,replicator_5
;   makerBotModelExtruder,mk13
;   makerBotSupportExtruder,mk14_s
;   makerBotModelMaterial,pla
;   makerBotSupportMaterial,pva
;   globalOffsetX,0.00000
;   globalOffsetY,0.00000
;   globalOffsetZ,0.00000
;   applyToolheadOffsets,0
;   buildVolumeShape,rectangular
;   buildVolumeX,300.00000
;   buildVolumeY,300.00000
;   buildVolumeZ,300.00000
;   buildVolumeDiameter,200.00000
;   originOffsetX,0.00000
;   originOffsetY,0.00000
;   originOffsetZ,0.00000
;   homingDirectionX,min
;   homingDirectionY,min
;   homingDirectionZ,min
;   mirrorVisualX,0
;   mirrorVisualY,1
;   mirrorVisualZ,0
;   machineBackgroundModel,Creality_K1Max.stl
;   startingScript,";TIME:[total_print_time_sec].00|;Filament used:{EVAL ""[total_filament_used]/1000""}m|;Layer height: [current_layer_height]|START_PRINT EXTRUDER_TEMP=[extruder0_temperature] BED_TEMP=[platform0_temperature]|M106 S[fan_speed_pwm] P0|M141 S50"
;   preLayerChangeScript,
;   postLayerChangeScript,
;   preRetractionScript,
;   postRetractionScript,
;   preToolChangeScript,
;   postToolChangeScript,
;   processChangeScript,
;   endingScript,END_PRINT|M106 S0 ; turn off cooling fan|
;   postProcessingScript,"C:\Users\Michael\git\preprocess_cancellation_MJ666\dist\preprocess_cancellation.exe ""[output_filepath]"""
;   useBridging,1
;   bridgingThresholdArea,50.00000
;   bridgingInfillExtraExpansion,0.00000
;   bridgingExtrusionModifier,100
;   bridgingSpeedModifier,100
;   overrideFanSpeedForBridging,1
;   bridgingFanSpeedPercentage,100
;   useFixedBridgingAngle,0
;   fixedBridgingAngle,0
;   applyBridgingToPerimeters,0
;   bridgingPerimeterExtraOverlap,0.00000
;   minBridgingPerimeterLength,10.00000
;   useToolChangeRetraction,1
;   toolChangeRetractDistance,12.00000
;   toolChangeExtraRestartDistance,-0.50000
;   toolChangeRetractSpeed,600.00000
;   toolChangePrimeOnFirstUse,0
;   toolChangeRetractAtEnd,0
;   externalThinWallType,perimeters_only
;   internalThinWallType,single_extrusions
;   thinWallAllowedOverlapPercentage,10
;   singleExtrusionMinLength,1.00000
;   singleExtrusionMinWidthPercentage,50
;   singleExtrusionMaxWidthPercentage,200
;   singleExtrusionEndpointExtensionDistance,0.20000
;   onlyRetractWhenCrossingOutlines,1
;   retractBetweenLayers,1
;   retractOnTopLayers,1
;   useRetractionMinTravel,0
;   retractionMinTravel,5.00000
;   useRetractionMinExtrusion,0
;   retractionMinExtrusion,3.00000
;   onlyVerticalLiftOnTopLayers,0
;   retractWhileWiping,0
;   wipingMode,outer_perimeter
;   avoidCrossingOutlines,0
;   maxMovementDetourFactor,3.00000
;   openLoopSlicingBehavior,heal
;   openLoopThickenWidth,0.50000
;   slicingRegionRepairMode,positive
;   processName,Process 4
;   autoConfigureMaterial,ABS
;   autoConfigureQuality,High
;   targetModels,cylinder_2
;   profileName,Creality K1 Max
;   profileVersion,2024-03-24 00:57:34
;   app,S3D-Software 5.1.2
;   technology,fff
;   baseProfile,
;   extruder,Primary Extruder
;   toolheadNumber,0
;   nozzleDiameter,0.40000
;   extrusionMultiplier,0.95000
;   extrusionWidthMode,manual
;   extrusionWidth,0.40000
;   useRetraction,1
;   retractDistance,0.50000
;   extraRestartDistance,0.00000
;   retractVerticalLift,0.00000
;   retractSpeed,2400.00000
;   useCoasting,0
;   coastingDistance,0.20000
;   useWiping,0
;   wipingDistance,5.00000
;   speedMaxFlowRate,1000.00000
;   toolheadOffsetX,0.00000
;   toolheadOffsetY,0.00000
;   filamentDiameter,1.75000
;   filamentPricePerKilogram,20.00000
;   filamentDensity,1.25000
;   primaryExtruder,Primary Extruder
;   layerHeight,0.10000
;   topSolidLayers,6
;   bottomSolidLayers,6
;   outlinePerimeters,4
;   useVaseMode,0
;   useAdaptiveLayerHeights,0
;   minAdaptiveLayerHeight,0.10000
;   maxAdaptiveLayerHeight,0.30000
;   adaptiveSmoothingLevel,5
;   horizontalOuterCompensation,0.00000
;   horizontalInnerCompensation,0.00000
;   firstLayerUnits,absolute
;   firstLayerHeightPercentage,150
;   firstLayerWidthPercentage,100
;   firstLayerSpeedPercentage,15
;   firstLayerHeightAbsolute,0.30000
;   firstLayerWidthAbsolute,0.40000
;   firstLayerSpeedAbsolute,1500.00000
;   startPointStrategy,closest
;   alignStartPointsX,0.00000
;   alignStartPointsY,0.00000
;   restrictStartPoints,1
;   perimeterPrintingOrder,inside_out
;   islandPrintingOrder,closest
;   printInfillBeforePerimeters,0
;   useSkirt,0
;   skirtExtruder,Primary Extruder
;   skirtLayers,1
;   skirtOffset,0.10000
;   skirtOutlines,3
;   useRaft,0
;   raftExtruder,Primary Extruder
;   raftBaseLayers,2
;   raftTopLayers,3
;   raftOffset,3.00000
;   raftSeparationDistance,0.14000
;   raftSpeedUnits,percentage
;   raftSpeedPercentage,30
;   raftSpeedAbsolute,600.00000
;   usePrimePillar,0
;   primePillarExtruder,All Extruders
;   primePillarWidth,12.00000
;   primePillarLocation,north_west
;   primePillarSpeedPercentage,100
;   primePillarInfillPercentage,100
;   autoStopPrimePillar,1
;   primePillarLayersAfterAutoStop,0
;   useOozeShield,0
;   oozeShieldExtruder,All Extruders
;   oozeShieldOffset,2.00000
;   oozeShieldOutlines,1
;   oozeShieldSidewallShape,waterfall
;   oozeShieldSidewallAngle,30
;   oozeShieldSpeedPercentage,100
;   autoStopOozeShield,1
;   oozeShieldLayersAfterAutoStop,0
;   sparseInfillExtruder,Primary Extruder
;   sparseInfillPattern,rectilinear
;   sparseInfillRotation,0
;   sparseInfillPercentage,30
;   sparseInfillExtrusionWidthPercentage,100
;   sparseInfillCombinedLayers,1
;   denseInfillLayers,0
;   denseInfillPercentage,50
;   infillOutlineOverlapPercentage,30
;   minInfillLength,5.00000
;   externalInfillPattern,rectilinear
;   externalInfillRotation,0
;   solidInfillThresholdArea,25.00000
;   solidInfillExtraExpansion,0.00000
;   useMonotonic,0
;   useDiaphragm,0
;   diaphragmSolidLayers,3
;   diaphragmSpacingLayers,20
;   topLayerExtraExpansion,1.00000
;   topLayerExtrusionModifier,100
;   overrideFanSpeedForTopLayer,0
;   topLayerFanSpeedPercentage,100
;   useIroning,0
;   ironingOutlineOffsetPercentage,50
;   ironingExtrusionWidthPercentage,25
;   ironingExtrusionModifier,15
;   ironingSpeedModifier,30
;   sparseSupportExtruder,Primary Extruder
;   sparseSupportInfillPattern,aligned
;   sparseSupportInfillRotation,0
;   sparseSupportInfillPercentage,40
;   sparseSupportOutlines,0
;   sparseSupportCombinedLayers,1
;   upperDenseSupportLayers,0
;   lowerDenseSupportLayers,0
;   denseSupportExtruder,Primary Extruder
;   denseSupportInfillPercentage,70
;   denseSupportExtraExpansion,0.00000
;   baseSupportLayers,1
;   supportInflationDistance,0.00000
;   supportHorizontalPartOffset,0.30000
;   supportUpperSeparationLayers,1
;   supportLowerSeparationLayers,1
;   temperatureController,Primary Extruder
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,extruder
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|260
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   temperatureController,Heated Build Platform
;   enableTemperatureController,1
;   temperatureNumber,0
;   temperatureType,platform
;   stabilizeAtStartup,1
;   temperatureSetpoints,1|110
;   useIdleCooldown,0
;   cooldownTemperature,150
;   cooldownRequiredIdleTime,180
;   cooldownReheatTime,60
;   fan,Cooling Fan
;   fanNumber,0
;   fanType,extruder
;   blipFanToFullPower,0
;   fanSetpoints,1|30
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,10.00000
;   maxQuickLayerFanSpeedPercentage,100
;   fan,Side Fan
;   fanNumber,2
;   fanType,environmental
;   blipFanToFullPower,0
;   fanSetpoints,1|0
;   increaseFanForQuickLayers,1
;   fanMaxQuickLayerTime,45.00000
;   fanMinQuickLayerTime,15.00000
;   maxQuickLayerFanSpeedPercentage,100
;   defaultPrintSpeed,27000.00000
;   outerPerimeterSpeedPercentage,70
;   innerPerimeterSpeedPercentage,80
;   topLayerSpeedPercentage,50
;   solidInfillSpeedPercentage,80
;   sparseSupportSpeedPercentage,80
;   denseSupportSpeedPercentage,70
;   travelSpeedXY,18000.00000
;   travelSpeedZ,2400.00000
;   reduceSpeedForQuickLayers,1
;   speedMaxQuickLayerTime,5.00000
;   minQuickLayerSpeedPercentage,70
;   reduceSpeedForShortPerimeters,1
;   speedMaxShortPerimeterLength,20.00000
;   minShortPerimeterSpeedPercentage,70
;   reduceSpeedForMaxFlowRate,0
;   accelXY,20000.00000
;   accelZ,500.00000
;   accelE,5000.00000
;   jerkXY,600.00000
;   jerkZ,24.00000
;   jerkE,300.00000
;   exportFileFormat,gcode
;   useStickyCommands,1
;   use5D,1
;   relativeExtrusionDistances,0
;   allowExtruderAxisZeroing,1
;   independentExtruderAxes,0
;   includeM10123,0
;   includeThumbnailImages,1
;   thumbnailImageEncoding,standard
;   thumbnailImageSizes,300|300,96|96
;   x3gMachineProfile,r2
;   overrideStepsPerMillimeter,0
;   stepsPerMillimeterX,88.57319
;   stepsPerMillimeterY,88.57319
;   stepsPerMillimeterZ,400.00000
;   stepsPerMillimeterA,96.27520
;   stepsPerMillimeterB,96.27520
;   xyzFileFormatVersion,1
;   makerBotMachineProfile,replicator_5
;   makerBotModelExtruder,mk13
;   makerBotSupportExtruder,mk14_s
;   makerBotModelMaterial,pla
;   makerBotSupportMaterial,pva
;   globalOffsetX,0.00000
;   globalOffsetY,0.00000
;   globalOffsetZ,0.00000
;   applyToolheadOffsets,0
;   buildVolumeShape,rectangular
;   buildVolumeX,300.00000
;   buildVolumeY,300.00000
;   buildVolumeZ,300.00000
;   buildVolumeDiameter,200.00000
;   originOffsetX,0.00000
;   originOffsetY,0.00000
;   originOffsetZ,0.00000
;   homingDirectionX,min
;   homingDirectionY,min
;   homingDirectionZ,min
;   mirrorVisualX,0
;   mirrorVisualY,1
;   mirrorVisualZ,0
;   machineBackgroundModel,Creality_K1Max.stl
;   startingScript,";TIME:[total_print_time_sec].00|;Filament used:{EVAL ""[total_filament_used]/1000""}m|;Layer height: [current_layer_height]|START_PRINT EXTRUDER_TEMP=[extruder0_temperature] BED_TEMP=[platform0_temperature]|M106 S[fan_speed_pwm] P0|M141 S50"
;   preLayerChangeScript,
;   postLayerChangeScript,
;   preRetractionScript,
;   postRetractionScript,
;   preToolChangeScript,
;   postToolChangeScript,
;   processChangeScript,
;   endingScript,END_PRINT|M106 S0 ; turn off cooling fan|
;   postProcessingScript,"C:\Users\Michael\git\preprocess_cancellation_MJ666\dist\preprocess_cancellation.exe ""[output_filepath]"""
;   useBridging,1
;   bridgingThresholdArea,50.00000
;   bridgingInfillExtraExpansion,0.00000
;   bridgingExtrusionModifier,100
;   bridgingSpeedModifier,100
;   overrideFanSpeedForBridging,1
;   bridgingFanSpeedPercentage,100
;   useFixedBridgingAngle,0
;   fixedBridgingAngle,0
;   applyBridgingToPerimeters,0
;   bridgingPerimeterExtraOverlap,0.00000
;   minBridgingPerimeterLength,10.00000
;   useToolChangeRetraction,1
;   toolChangeRetractDistance,12.00000
;   toolChangeExtraRestartDistance,-0.50000
;   toolChangeRetractSpeed,600.00000
;   toolChangePrimeOnFirstUse,0
;   toolChangeRetractAtEnd,0
;   externalThinWallType,perimeters_only
;   internalThinWallType,single_extrusions
;   thinWallAllowedOverlapPercentage,10
;   singleExtrusionMinLength,1.00000
;   singleExtrusionMinWidthPercentage,50
;   singleExtrusionMaxWidthPercentage,200
;   singleExtrusionEndpointExtensionDistance,0.20000
;   onlyRetractWhenCrossingOutlines,1
;   retractBetweenLayers,1
;   retractOnTopLayers,1
;   useRetractionMinTravel,0
;   retractionMinTravel,5.00000
;   useRetractionMinExtrusion,0
;   retractionMinExtrusion,3.00000
;   onlyVerticalLiftOnTopLayers,0
;   retractWhileWiping,0
;   wipingMode,outer_perimeter
;   avoidCrossingOutlines,0
;   maxMovementDetourFactor,3.00000
;   openLoopSlicingBehavior,heal
;   openLoopThickenWidth,0.50000
;   slicingRegionRepairMode,positive
G90
M82
M106 S255 P0
M106 S0 P2
;TIME:191.00
;Filament used:0.2914m
;Layer height: 0.3000
START_PRINT EXTRUDER_TEMP=260 BED_TEMP=110
M106 S255 P0
M141 S50
; process Process 1
; layer 1, Z = 0.3000
T0
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
; tool H0.3000 W0.400
G1 Z0.3000 F2400
G1 X138.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y143.900 E0.10427 F735
G1 X141.100 Y146.100 E0.20854
G1 X138.900 Y146.100 E0.31281
G1 X138.900 Y143.900 E0.41708
G1 X138.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y143.500 E0.14219 F735
G1 X141.500 Y146.500 E0.28437
G1 X138.500 Y146.500 E0.42656
G1 X138.500 Y143.500 E0.56875
G1 X138.100 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y143.100 E0.18010 F798
G1 X141.900 Y146.900 E0.36021
G1 X138.100 Y146.900 E0.54031
G1 X138.100 Y143.100 E0.72041
; feature outer perimeter
G1 X137.700 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y142.700 E0.21802 F966
G1 X142.300 Y147.300 E0.43604
G1 X137.700 Y147.300 E0.65406
G1 X137.700 Y142.700 E0.87208
; feature solid layer
G1 X140.311 Y144.180 F18000
G92 E0.00000
G1 X140.820 Y144.689 E0.03410 F1050
G1 X140.820 Y145.254 E0.06091
G1 X139.746 Y144.180 E0.13292
G1 X139.180 Y144.180 E0.15973
G1 X140.820 Y145.820 E0.26966
G1 X140.254 Y145.820 E0.29647
G1 X139.180 Y144.746 E0.36847
G1 X139.180 Y145.311 E0.39528
G1 X139.689 Y145.820 E0.42937
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X148.900 Y143.900 E0.10427 F735
G1 X151.100 Y143.900 E0.20854
G1 X151.100 Y146.100 E0.31281
G1 X148.900 Y146.100 E0.41708
G1 X148.500 Y146.500 F18000
G92 E0.00000
G1 X148.500 Y143.500 E0.14219 F735
G1 X151.500 Y143.500 E0.28437
G1 X151.500 Y146.500 E0.42656
G1 X148.500 Y146.500 E0.56875
G1 X148.100 Y146.900 F18000
G92 E0.00000
G1 X148.100 Y143.100 E0.18010 F798
G1 X151.900 Y143.100 E0.36021
G1 X151.900 Y146.900 E0.54031
G1 X148.100 Y146.900 E0.72041
; feature outer perimeter
G1 X147.700 Y147.300 F18000
G92 E0.00000
G1 X147.700 Y142.700 E0.21802 F966
G1 X152.300 Y142.700 E0.43604
G1 X152.300 Y147.300 E0.65406
G1 X147.700 Y147.300 E0.87208
; feature solid layer
G1 X149.689 Y145.820 F18000
G92 E0.00000
G1 X149.180 Y145.311 E0.03409 F1050
G1 X149.180 Y144.746 E0.06090
G1 X150.254 Y145.820 E0.13291
G1 X150.820 Y145.820 E0.15972
G1 X149.180 Y144.180 E0.26964
G1 X149.746 Y144.180 E0.29645
G1 X150.820 Y145.254 E0.36846
G1 X150.820 Y144.689 E0.39527
G1 X150.311 Y144.180 E0.42937
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
M106 S249 P0
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.10427 F1050
G1 X148.900 Y156.100 E0.20854
G1 X148.900 Y153.900 E0.31281
G1 X151.100 Y153.900 E0.41708
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.14219 F1050
G1 X148.500 Y156.500 E0.28437
G1 X148.500 Y153.500 E0.42656
G1 X151.500 Y153.500 E0.56875
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.18010 F1140
G1 X148.100 Y156.900 E0.36021
G1 X148.100 Y153.100 E0.54031
G1 X151.900 Y153.100 E0.72041
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.21802 F1380
G1 X147.700 Y157.300 E0.43604
G1 X147.700 Y152.700 E0.65406
G1 X152.300 Y152.700 E0.87208
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.02799 F1500
G1 X150.820 Y155.163 E0.05480
G1 X149.837 Y154.180 E0.12070
G1 X149.271 Y154.180 E0.14751
G1 X150.820 Y155.729 E0.25133
G1 X150.820 Y155.820 E0.25565
G1 X150.345 Y155.820 E0.27814
G1 X149.180 Y154.655 E0.35626
G1 X149.180 Y155.220 E0.38307
G1 X149.780 Y155.820 E0.42327
G1 X149.214 Y155.820 E0.45008
G1 X149.180 Y155.786 E0.45236
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.10427 F1050
G1 X138.900 Y153.900 E0.20854
G1 X141.100 Y153.900 E0.31281
G1 X141.100 Y156.100 E0.41708
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.14219 F1050
G1 X138.500 Y153.500 E0.28437
G1 X141.500 Y153.500 E0.42656
G1 X141.500 Y156.500 E0.56875
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.18010 F1140
G1 X138.100 Y153.100 E0.36021
G1 X141.900 Y153.100 E0.54031
G1 X141.900 Y156.900 E0.72041
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.21802 F1380
G1 X137.700 Y152.700 E0.43604
G1 X142.300 Y152.700 E0.65406
G1 X142.300 Y157.300 E0.87208
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.02798 F1500
G1 X139.180 Y154.837 E0.05479
G1 X140.163 Y155.820 E0.12068
G1 X140.729 Y155.820 E0.14749
G1 X139.180 Y154.271 E0.25130
G1 X139.180 Y154.180 E0.25563
G1 X139.654 Y154.180 E0.27811
G1 X140.820 Y155.346 E0.35624
G1 X140.820 Y154.780 E0.38305
G1 X140.220 Y154.180 E0.42326
G1 X140.786 Y154.180 E0.45007
G1 X140.820 Y154.214 E0.45236
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.38011 F1500
G1 X149.010 Y158.600 E0.39907
G1 X140.990 Y158.600 E0.77919
G1 X140.990 Y158.200 E0.79815
G1 X149.010 Y158.200 E1.17826
G1 X149.010 Y158.010 E1.18727
G1 X146.990 Y158.010 E1.28301
G1 X146.990 Y157.800 E1.29296
G1 X143.010 Y157.800 E1.48160
G1 X143.010 Y157.400 E1.50055
G1 X146.990 Y157.400 E1.68919
G1 X146.990 Y157.000 E1.70815
G1 X143.010 Y157.000 E1.89678
G1 X143.010 Y156.600 E1.91574
G1 X146.990 Y156.600 E2.10438
G1 X146.990 Y156.200 E2.12333
G1 X143.010 Y156.200 E2.31197
G1 X143.010 Y155.800 E2.33093
G1 X146.990 Y155.800 E2.51956
G1 X146.990 Y155.400 E2.53852
G1 X143.010 Y155.400 E2.72716
G1 X143.010 Y155.000 E2.74612
G1 X146.990 Y155.000 E2.93475
G1 X146.990 Y154.600 E2.95371
G1 X143.010 Y154.600 E3.14234
G1 X143.010 Y154.200 E3.16130
G1 X146.990 Y154.200 E3.34994
G1 X146.990 Y153.800 E3.36890
G1 X143.010 Y153.800 E3.55753
G1 X143.010 Y153.400 E3.57649
G1 X146.990 Y153.400 E3.76513
G1 X146.990 Y153.000 E3.78408
G1 X143.010 Y153.000 E3.97272
G1 X143.010 Y152.600 E3.99168
G1 X146.990 Y152.600 E4.18031
G1 X146.990 Y152.200 E4.19927
G1 X143.010 Y152.200 E4.38791
G1 X143.010 Y151.990 E4.39787
G1 X140.990 Y151.990 E4.49360
G1 X140.990 Y151.800 E4.50260
G1 X149.010 Y151.800 E4.88272
G1 X149.010 Y151.400 E4.90167
G1 X140.990 Y151.400 E5.28179
G1 X140.990 Y151.000 E5.30075
G1 X149.010 Y151.000 E5.68086
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
M106 S255 P0
; feature inner perimeter
G1 X159.036 Y145.526 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.989 Y145.427 E0.00519 F735
G1 X158.950 Y145.322 E0.01050
G1 X158.924 Y145.217 E0.01565
G1 X158.907 Y145.108 E0.02086
G1 X158.902 Y145.002 E0.02590
G1 X158.907 Y144.889 E0.03128
G1 X158.920 Y144.802 E0.03541
G1 X158.976 Y144.604 E0.04517
G1 X159.010 Y144.523 E0.04936
G1 X159.063 Y144.427 E0.05455
G1 X159.125 Y144.336 E0.05974
G1 X159.195 Y144.252 E0.06495
G1 X159.271 Y144.178 E0.06999
G1 X159.360 Y144.107 E0.07537
G1 X159.449 Y144.050 E0.08037
G1 X159.549 Y143.998 E0.08573
G1 X159.650 Y143.958 E0.09088
G1 X159.756 Y143.928 E0.09608
G1 X159.861 Y143.910 E0.10112
G1 X159.956 Y143.903 E0.10566
G1 X160.154 Y143.913 E0.11504
G1 X160.244 Y143.928 E0.11940
G1 X160.350 Y143.958 E0.12459
G1 X160.452 Y143.998 E0.12979
G1 X160.547 Y144.047 E0.13484
G1 X160.642 Y144.108 E0.14020
G1 X160.727 Y144.176 E0.14535
G1 X160.805 Y144.252 E0.15053
G1 X160.875 Y144.336 E0.15572
G1 X160.937 Y144.427 E0.16092
G1 X160.990 Y144.523 E0.16611
G1 X161.032 Y144.624 E0.17129
G1 X161.064 Y144.728 E0.17648
G1 X161.086 Y144.836 E0.18168
G1 X161.095 Y144.927 E0.18602
G1 X161.090 Y145.126 E0.19546
G1 X161.076 Y145.217 E0.19981
G1 X161.049 Y145.323 E0.20503
G1 X161.013 Y145.423 E0.21007
G1 X160.964 Y145.525 E0.21543
G1 X160.909 Y145.616 E0.22044
G1 X160.841 Y145.705 E0.22577
G1 X160.765 Y145.787 E0.23108
G1 X160.685 Y145.858 E0.23613
G1 X160.596 Y145.922 E0.24133
G1 X160.501 Y145.977 E0.24651
G1 X160.401 Y146.022 E0.25171
G1 X160.298 Y146.056 E0.25690
G1 X160.191 Y146.081 E0.26209
G1 X160.099 Y146.092 E0.26645
G1 X159.901 Y146.092 E0.27587
G1 X159.809 Y146.081 E0.28024
G1 X159.702 Y146.056 E0.28543
G1 X159.601 Y146.023 E0.29048
G1 X159.498 Y145.976 E0.29584
G1 X159.404 Y145.922 E0.30098
G1 X159.315 Y145.858 E0.30620
G1 X159.235 Y145.787 E0.31124
G1 X159.158 Y145.704 E0.31661
G1 X159.094 Y145.620 E0.32163
G1 X159.036 Y145.526 E0.32685
G1 X158.685 Y145.718 F18000
G92 E0.00000
G1 X158.620 Y145.584 E0.00708 F735
G1 X158.568 Y145.440 E0.01430
G1 X158.531 Y145.296 E0.02136
G1 X158.509 Y145.148 E0.02845
G1 X158.501 Y145.002 E0.03538
G1 X158.509 Y144.849 E0.04264
G1 X158.528 Y144.718 E0.04892
G1 X158.598 Y144.472 E0.06105
G1 X158.650 Y144.349 E0.06736
G1 X158.721 Y144.218 E0.07445
G1 X158.805 Y144.094 E0.08153
G1 X158.902 Y143.980 E0.08863
G1 X159.006 Y143.878 E0.09555
G1 X159.126 Y143.782 E0.10281
G1 X159.248 Y143.703 E0.10972
G1 X159.384 Y143.633 E0.11697
G1 X159.523 Y143.579 E0.12402
G1 X159.667 Y143.538 E0.13112
G1 X159.811 Y143.513 E0.13804
G1 X159.951 Y143.502 E0.14470
G1 X160.199 Y143.514 E0.15647
G1 X160.333 Y143.538 E0.16295
G1 X160.477 Y143.579 E0.17004
G1 X160.617 Y143.633 E0.17713
G1 X160.747 Y143.700 E0.18406
G1 X160.875 Y143.783 E0.19131
G1 X160.992 Y143.876 E0.19836
G1 X161.099 Y143.980 E0.20544
G1 X161.195 Y144.094 E0.21252
G1 X161.279 Y144.218 E0.21961
G1 X161.350 Y144.349 E0.22669
G1 X161.408 Y144.487 E0.23377
G1 X161.452 Y144.629 E0.24085
G1 X161.482 Y144.776 E0.24793
G1 X161.496 Y144.912 E0.25442
G1 X161.489 Y145.161 E0.26622
G1 X161.469 Y145.296 E0.27270
G1 X161.432 Y145.441 E0.27980
G1 X161.382 Y145.579 E0.28673
G1 X161.316 Y145.717 E0.29398
G1 X161.240 Y145.841 E0.30089
G1 X161.148 Y145.963 E0.30812
G1 X161.044 Y146.074 E0.31534
G1 X160.935 Y146.171 E0.32226
G1 X160.813 Y146.258 E0.32936
G1 X160.684 Y146.333 E0.33644
G1 X160.548 Y146.394 E0.34352
G1 X160.406 Y146.442 E0.35060
G1 X160.260 Y146.475 E0.35768
G1 X160.124 Y146.492 E0.36417
G1 X159.876 Y146.492 E0.37596
G1 X159.740 Y146.475 E0.38246
G1 X159.594 Y146.442 E0.38954
G1 X159.455 Y146.395 E0.39647
G1 X159.316 Y146.333 E0.40373
G1 X159.187 Y146.258 E0.41077
G1 X159.065 Y146.171 E0.41788
G1 X158.956 Y146.074 E0.42480
G1 X158.851 Y145.962 E0.43206
G1 X158.763 Y145.846 E0.43897
G1 X158.685 Y145.718 E0.44607
G1 X158.334 Y145.910 F18000
G92 E0.00000
G1 X158.251 Y145.740 E0.00898 F735
G1 X158.185 Y145.559 E0.01810
G1 X158.138 Y145.376 E0.02706
G1 X158.110 Y145.188 E0.03604
G1 X158.101 Y145.003 E0.04485
G1 X158.110 Y144.810 E0.05401
G1 X158.137 Y144.634 E0.06243
G1 X158.220 Y144.339 E0.07693
G1 X158.289 Y144.175 E0.08538
G1 X158.379 Y144.009 E0.09435
G1 X158.486 Y143.853 E0.10332
G1 X158.608 Y143.707 E0.11231
G1 X158.741 Y143.577 E0.12112
G1 X158.892 Y143.457 E0.13027
G1 X159.048 Y143.356 E0.13907
G1 X159.219 Y143.268 E0.14821
G1 X159.395 Y143.199 E0.15717
G1 X159.578 Y143.148 E0.16615
G1 X159.761 Y143.115 E0.17496
G1 X159.946 Y143.101 E0.18375
G1 X160.244 Y143.116 E0.19789
G1 X160.423 Y143.148 E0.20651
G1 X160.605 Y143.199 E0.21549
G1 X160.781 Y143.268 E0.22446
G1 X160.947 Y143.353 E0.23328
G1 X161.109 Y143.457 E0.24242
G1 X161.257 Y143.575 E0.25138
G1 X161.392 Y143.707 E0.26035
G1 X161.514 Y143.852 E0.26933
G1 X161.621 Y144.009 E0.27830
G1 X161.711 Y144.175 E0.28728
G1 X161.785 Y144.350 E0.29625
G1 X161.841 Y144.531 E0.30522
G1 X161.878 Y144.716 E0.31420
G1 X161.896 Y144.897 E0.32281
G1 X161.889 Y145.196 E0.33698
G1 X161.862 Y145.375 E0.34559
G1 X161.815 Y145.559 E0.35458
G1 X161.751 Y145.734 E0.36339
G1 X161.668 Y145.908 E0.37253
G1 X161.571 Y146.066 E0.38133
G1 X161.455 Y146.220 E0.39047
G1 X161.324 Y146.361 E0.39959
G1 X161.184 Y146.484 E0.40840
G1 X161.030 Y146.595 E0.41738
G1 X160.867 Y146.689 E0.42636
G1 X160.694 Y146.767 E0.43533
G1 X160.514 Y146.827 E0.44431
G1 X160.330 Y146.870 E0.45328
G1 X160.149 Y146.892 E0.46190
G1 X159.851 Y146.892 E0.47605
G1 X159.670 Y146.870 E0.48468
G1 X159.486 Y146.827 E0.49365
G1 X159.309 Y146.768 E0.50246
G1 X159.133 Y146.689 E0.51162
G1 X158.970 Y146.595 E0.52057
G1 X158.816 Y146.484 E0.52956
G1 X158.676 Y146.361 E0.53836
G1 X158.545 Y146.220 E0.54751
G1 X158.433 Y146.072 E0.55632
G1 X158.334 Y145.910 E0.56530
; feature outer perimeter
G1 X157.982 Y146.102 F18000
G92 E0.00000
G1 X157.882 Y145.896 E0.01087 F758
G1 X157.802 Y145.677 E0.02189
G1 X157.746 Y145.455 E0.03276
G1 X157.712 Y145.228 E0.04363
G1 X157.700 Y145.003 E0.05432
G1 X157.712 Y144.770 E0.06536
G1 X157.745 Y144.550 E0.07593
G1 X157.841 Y144.207 E0.09281
G1 X157.928 Y144.001 E0.10338
G1 X158.038 Y143.800 E0.11424
G1 X158.167 Y143.611 E0.12511
G1 X158.314 Y143.435 E0.13598
G1 X158.476 Y143.277 E0.14667
G1 X158.658 Y143.132 E0.15772
G1 X158.847 Y143.009 E0.16840
G1 X159.054 Y142.903 E0.17945
G1 X159.268 Y142.819 E0.19030
G1 X159.488 Y142.757 E0.20118
G1 X159.711 Y142.718 E0.21187
G1 X159.940 Y142.700 E0.22279
G1 X160.288 Y142.718 E0.23931
G1 X160.512 Y142.757 E0.25006
G1 X160.733 Y142.819 E0.26093
G1 X160.946 Y142.903 E0.27179
G1 X161.147 Y143.006 E0.28249
G1 X161.343 Y143.132 E0.29353
G1 X161.522 Y143.275 E0.30439
G1 X161.686 Y143.435 E0.31526
G1 X161.833 Y143.611 E0.32613
G1 X161.962 Y143.800 E0.33699
G1 X162.072 Y144.001 E0.34786
G1 X162.161 Y144.213 E0.35872
G1 X162.229 Y144.432 E0.36959
G1 X162.274 Y144.656 E0.38045
G1 X162.297 Y144.882 E0.39120
G1 X162.288 Y145.231 E0.40773
G1 X162.254 Y145.455 E0.41848
G1 X162.198 Y145.677 E0.42934
G1 X162.120 Y145.889 E0.44004
G1 X162.020 Y146.099 E0.45108
G1 X161.902 Y146.292 E0.46177
G1 X161.762 Y146.477 E0.47281
G1 X161.603 Y146.648 E0.48384
G1 X161.434 Y146.797 E0.49454
G1 X161.248 Y146.931 E0.50540
G1 X161.049 Y147.046 E0.51627
G1 X160.840 Y147.140 E0.52713
G1 X160.623 Y147.213 E0.53800
G1 X160.399 Y147.264 E0.54887
G1 X160.174 Y147.292 E0.55962
G1 X159.826 Y147.292 E0.57614
G1 X159.601 Y147.264 E0.58689
G1 X159.377 Y147.213 E0.59776
G1 X159.163 Y147.141 E0.60845
G1 X158.951 Y147.046 E0.61950
G1 X158.752 Y146.931 E0.63035
G1 X158.566 Y146.797 E0.64122
G1 X158.397 Y146.648 E0.65192
G1 X158.238 Y146.477 E0.66296
G1 X158.102 Y146.298 E0.67365
G1 X157.982 Y146.102 E0.68452
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.317 Y145.447 E0.01591 F1050
G1 X159.282 Y145.391 E0.01901
G1 X159.247 Y145.318 E0.02286
G1 X159.218 Y145.239 E0.02684
G1 X159.198 Y145.161 E0.03067
G1 X159.186 Y145.080 E0.03454
G1 X159.182 Y145.002 E0.03828
G1 X159.186 Y144.916 E0.04232
G1 X159.195 Y144.861 E0.04496
G1 X159.217 Y144.782 E0.04887
G1 X160.222 Y145.787 E0.11621
G1 X160.299 Y145.761 E0.12008
G1 X160.373 Y145.727 E0.12394
G1 X160.444 Y145.686 E0.12780
G1 X160.510 Y145.639 E0.13168
G1 X160.569 Y145.586 E0.13541
G1 X160.578 Y145.577 E0.13601
G1 X159.422 Y144.422 E0.21347
G1 X159.457 Y144.388 E0.21577
G1 X159.524 Y144.334 E0.21981
G1 X159.589 Y144.292 E0.22350
G1 X159.665 Y144.253 E0.22753
G1 X159.740 Y144.224 E0.23135
G1 X159.779 Y144.213 E0.23330
G1 X160.787 Y145.220 E0.30083
G1 X160.802 Y145.161 E0.30371
G1 X160.811 Y145.101 E0.30659
G1 X160.815 Y144.937 E0.31436
G1 X160.809 Y144.877 E0.31722
G1 X160.793 Y144.797 E0.32109
G1 X160.769 Y144.719 E0.32496
G1 X160.737 Y144.644 E0.32881
G1 X160.698 Y144.573 E0.33268
G1 X160.683 Y144.551 E0.33393
G1 X160.449 Y144.317 E0.34962
G92 E0.00000
G1 E-0.50000 F2400
; layer 2, Z = 0.4000
; feature inner perimeter
; tool H0.1000 W0.400
G1 Z0.4000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.924 Y144.782 E0.07438
G1 X158.951 Y144.676 E0.07611
G1 X158.982 Y144.589 E0.07756
G1 X159.073 Y144.412 E0.08070
G1 X159.125 Y144.336 E0.08215
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08735
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09427
G1 X159.863 Y143.909 E0.09599
G1 X159.954 Y143.903 E0.09742
G1 X160.160 Y143.913 E0.10069
G1 X160.244 Y143.928 E0.10203
G1 X160.350 Y143.958 E0.10377
G1 X160.452 Y143.998 E0.10550
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.531 Y144.702 E0.10150
G1 X158.568 Y144.557 E0.10386
G1 X158.615 Y144.429 E0.10602
G1 X158.728 Y144.208 E0.10995
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.949 Y143.502 E0.13315
G1 X160.206 Y143.515 E0.13721
G1 X160.333 Y143.538 E0.13925
G1 X160.477 Y143.579 E0.14162
G1 X160.616 Y143.633 E0.14398
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.138 Y144.623 E0.12862
G1 X158.185 Y144.439 E0.13162
G1 X158.247 Y144.269 E0.13449
G1 X158.384 Y144.003 E0.13921
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14508
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15106
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.944 Y143.101 E0.16887
G1 X160.251 Y143.117 E0.17373
G1 X160.422 Y143.148 E0.17647
G1 X160.605 Y143.199 E0.17947
G1 X160.781 Y143.268 E0.18246
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.746 Y144.544 E0.15575
G1 X157.802 Y144.321 E0.15937
G1 X157.880 Y144.108 E0.16295
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17205
G1 X158.314 Y143.435 E0.17567
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19016
G1 X159.268 Y142.819 E0.19378
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.940 Y142.700 E0.20460
G1 X160.297 Y142.719 E0.21025
G1 X160.512 Y142.757 E0.21369
G1 X160.733 Y142.819 E0.21732
G1 X160.946 Y142.903 E0.22094
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.221 Y144.213 E0.10035
G1 X160.181 Y144.202 E0.10101
G1 X160.128 Y144.192 E0.10185
G1 X159.957 Y144.183 E0.10457
G1 X159.898 Y144.188 E0.10549
G1 X159.818 Y144.202 E0.10678
G1 X159.739 Y144.224 E0.10807
G1 X159.664 Y144.254 E0.10936
G1 X159.591 Y144.291 E0.11065
G1 X159.552 Y144.316 E0.11139
G1 X159.317 Y144.551 E0.11664
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 3, Z = 0.5000
; feature inner perimeter
G1 Z0.5000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09340
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12038
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12510
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 4, Z = 0.6000
; feature inner perimeter
G1 Z0.6000 F2400
G1 X160.596 Y144.077 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.685 Y144.141 E0.00173 F10584
G1 X160.767 Y144.213 E0.00346
G1 X160.841 Y144.293 E0.00519
G1 X160.907 Y144.380 E0.00692
G1 X160.965 Y144.474 E0.00865
G1 X161.012 Y144.573 E0.01038
G1 X161.049 Y144.675 E0.01211
G1 X161.076 Y144.782 E0.01384
G1 X161.093 Y144.891 E0.01559
G1 X161.097 Y144.971 E0.01686
G1 X161.082 Y145.182 E0.02020
G1 X161.064 Y145.270 E0.02162
G1 X161.032 Y145.375 E0.02334
G1 X160.990 Y145.476 E0.02508
G1 X160.937 Y145.572 E0.02681
G1 X160.875 Y145.662 E0.02853
G1 X160.805 Y145.746 E0.03027
G1 X160.727 Y145.823 E0.03199
G1 X160.641 Y145.891 E0.03372
G1 X160.549 Y145.950 E0.03545
G1 X160.452 Y146.000 E0.03718
G1 X160.350 Y146.040 E0.03891
G1 X160.244 Y146.070 E0.04064
G1 X160.136 Y146.089 E0.04237
G1 X160.027 Y146.097 E0.04410
G1 X159.918 Y146.094 E0.04583
G1 X159.809 Y146.081 E0.04756
G1 X159.703 Y146.056 E0.04929
G1 X159.599 Y146.022 E0.05102
G1 X159.499 Y145.977 E0.05275
G1 X159.404 Y145.922 E0.05448
G1 X159.315 Y145.858 E0.05621
G1 X159.233 Y145.785 E0.05794
G1 X159.159 Y145.705 E0.05967
G1 X159.093 Y145.618 E0.06140
G1 X159.035 Y145.524 E0.06313
G1 X158.988 Y145.426 E0.06486
G1 X158.951 Y145.323 E0.06659
G1 X158.923 Y145.217 E0.06832
G1 X158.907 Y145.109 E0.07005
G1 X158.902 Y144.999 E0.07178
G1 X158.907 Y144.890 E0.07351
G1 X158.924 Y144.782 E0.07524
G1 X158.951 Y144.676 E0.07697
G1 X158.982 Y144.589 E0.07842
G1 X159.073 Y144.412 E0.08156
G1 X159.125 Y144.336 E0.08301
G1 X159.195 Y144.252 E0.08475
G1 X159.273 Y144.176 E0.08647
G1 X159.359 Y144.107 E0.08821
G1 X159.451 Y144.048 E0.08993
G1 X159.548 Y143.998 E0.09167
G1 X159.650 Y143.958 E0.09339
G1 X159.756 Y143.928 E0.09513
G1 X159.863 Y143.909 E0.09685
G1 X159.972 Y143.901 E0.09858
G1 X160.082 Y143.904 E0.10031
G1 X160.191 Y143.918 E0.10205
G1 X160.297 Y143.942 E0.10377
G1 X160.401 Y143.977 E0.10550
G1 X160.501 Y144.022 E0.10724
G1 X160.596 Y144.077 E0.10896
G1 X160.813 Y143.740 F18000
G92 E0.00000
G1 X160.934 Y143.827 E0.00236 F10584
G1 X161.047 Y143.926 E0.00472
G1 X161.148 Y144.036 E0.00708
G1 X161.238 Y144.155 E0.00944
G1 X161.316 Y144.283 E0.01180
G1 X161.381 Y144.417 E0.01416
G1 X161.432 Y144.557 E0.01652
G1 X161.469 Y144.702 E0.01888
G1 X161.491 Y144.851 E0.02126
G1 X161.498 Y144.975 E0.02323
G1 X161.479 Y145.237 E0.02737
G1 X161.452 Y145.369 E0.02950
G1 X161.408 Y145.512 E0.03186
G1 X161.350 Y145.649 E0.03422
G1 X161.279 Y145.781 E0.03658
G1 X161.195 Y145.904 E0.03894
G1 X161.099 Y146.019 E0.04130
G1 X160.992 Y146.123 E0.04366
G1 X160.875 Y146.216 E0.04602
G1 X160.749 Y146.297 E0.04839
G1 X160.616 Y146.365 E0.05075
G1 X160.477 Y146.420 E0.05311
G1 X160.333 Y146.460 E0.05547
G1 X160.186 Y146.486 E0.05783
G1 X160.037 Y146.498 E0.06019
G1 X159.888 Y146.494 E0.06255
G1 X159.740 Y146.475 E0.06491
G1 X159.594 Y146.442 E0.06727
G1 X159.452 Y146.394 E0.06963
G1 X159.316 Y146.333 E0.07199
G1 X159.187 Y146.258 E0.07435
G1 X159.066 Y146.171 E0.07671
G1 X158.954 Y146.072 E0.07907
G1 X158.852 Y145.963 E0.08143
G1 X158.762 Y145.844 E0.08379
G1 X158.684 Y145.716 E0.08616
G1 X158.619 Y145.581 E0.08851
G1 X158.568 Y145.441 E0.09087
G1 X158.531 Y145.296 E0.09324
G1 X158.509 Y145.148 E0.09560
G1 X158.501 Y144.999 E0.09796
G1 X158.509 Y144.850 E0.10032
G1 X158.531 Y144.702 E0.10268
G1 X158.568 Y144.557 E0.10504
G1 X158.615 Y144.429 E0.10720
G1 X158.728 Y144.208 E0.11113
G1 X158.805 Y144.094 E0.11329
G1 X158.901 Y143.980 E0.11566
G1 X159.008 Y143.876 E0.11801
G1 X159.125 Y143.782 E0.12038
G1 X159.251 Y143.701 E0.12273
G1 X159.384 Y143.633 E0.12510
G1 X159.523 Y143.579 E0.12746
G1 X159.667 Y143.538 E0.12982
G1 X159.814 Y143.512 E0.13218
G1 X159.962 Y143.501 E0.13454
G1 X160.112 Y143.505 E0.13690
G1 X160.260 Y143.523 E0.13926
G1 X160.406 Y143.557 E0.14162
G1 X160.548 Y143.604 E0.14398
G1 X160.684 Y143.666 E0.14634
G1 X160.813 Y143.740 E0.14870
G1 X161.030 Y143.404 F18000
G92 E0.00000
G1 X161.184 Y143.514 E0.00299 F10584
G1 X161.326 Y143.640 E0.00598
G1 X161.455 Y143.778 E0.00897
G1 X161.569 Y143.929 E0.01196
G1 X161.668 Y144.091 E0.01496
G1 X161.750 Y144.261 E0.01795
G1 X161.815 Y144.439 E0.02094
G1 X161.862 Y144.623 E0.02393
G1 X161.890 Y144.811 E0.02693
G1 X161.899 Y144.979 E0.02960
G1 X161.876 Y145.291 E0.03453
G1 X161.841 Y145.468 E0.03739
G1 X161.785 Y145.649 E0.04038
G1 X161.711 Y145.823 E0.04337
G1 X161.621 Y145.990 E0.04636
G1 X161.514 Y146.146 E0.04935
G1 X161.392 Y146.291 E0.05234
G1 X161.257 Y146.423 E0.05533
G1 X161.109 Y146.541 E0.05833
G1 X160.950 Y146.644 E0.06132
G1 X160.781 Y146.730 E0.06431
G1 X160.605 Y146.800 E0.06730
G1 X160.423 Y146.851 E0.07029
G1 X160.236 Y146.884 E0.07328
G1 X160.047 Y146.898 E0.07627
G1 X159.858 Y146.893 E0.07926
G1 X159.670 Y146.870 E0.08226
G1 X159.486 Y146.828 E0.08525
G1 X159.306 Y146.767 E0.08824
G1 X159.134 Y146.689 E0.09123
G1 X158.970 Y146.595 E0.09422
G1 X158.816 Y146.484 E0.09721
G1 X158.674 Y146.359 E0.10020
G1 X158.545 Y146.220 E0.10320
G1 X158.431 Y146.069 E0.10619
G1 X158.332 Y145.907 E0.10918
G1 X158.250 Y145.737 E0.11217
G1 X158.185 Y145.559 E0.11516
G1 X158.138 Y145.376 E0.11815
G1 X158.110 Y145.188 E0.12114
G1 X158.101 Y144.999 E0.12413
G1 X158.110 Y144.810 E0.12712
G1 X158.138 Y144.623 E0.13012
G1 X158.185 Y144.439 E0.13311
G1 X158.247 Y144.269 E0.13598
G1 X158.384 Y144.003 E0.14070
G1 X158.486 Y143.853 E0.14357
G1 X158.608 Y143.707 E0.14657
G1 X158.743 Y143.575 E0.14955
G1 X158.891 Y143.457 E0.15255
G1 X159.050 Y143.355 E0.15554
G1 X159.219 Y143.268 E0.15853
G1 X159.395 Y143.199 E0.16152
G1 X159.577 Y143.148 E0.16451
G1 X159.764 Y143.115 E0.16750
G1 X159.953 Y143.101 E0.17049
G1 X160.142 Y143.105 E0.17349
G1 X160.330 Y143.129 E0.17648
G1 X160.514 Y143.171 E0.17947
G1 X160.694 Y143.231 E0.18246
G1 X160.866 Y143.309 E0.18545
G1 X161.030 Y143.404 E0.18844
; feature outer perimeter
G1 X161.248 Y143.067 F18000
G92 E0.00000
G1 X161.434 Y143.201 E0.00362 F9554
G1 X161.606 Y143.353 E0.00725
G1 X161.762 Y143.521 E0.01087
G1 X161.900 Y143.704 E0.01449
G1 X162.020 Y143.899 E0.01811
G1 X162.119 Y144.106 E0.02173
G1 X162.198 Y144.321 E0.02536
G1 X162.254 Y144.544 E0.02898
G1 X162.288 Y144.770 E0.03260
G1 X162.299 Y144.984 E0.03597
G1 X162.273 Y145.345 E0.04170
G1 X162.229 Y145.567 E0.04527
G1 X162.161 Y145.786 E0.04889
G1 X162.072 Y145.997 E0.05252
G1 X161.962 Y146.198 E0.05614
G1 X161.833 Y146.388 E0.05976
G1 X161.686 Y146.563 E0.06338
G1 X161.522 Y146.723 E0.06700
G1 X161.342 Y146.867 E0.07063
G1 X161.150 Y146.991 E0.07425
G1 X160.946 Y147.095 E0.07787
G1 X160.733 Y147.179 E0.08149
G1 X160.512 Y147.241 E0.08512
G1 X160.286 Y147.281 E0.08874
G1 X160.057 Y147.298 E0.09236
G1 X159.828 Y147.293 E0.09598
G1 X159.601 Y147.264 E0.09960
G1 X159.377 Y147.213 E0.10323
G1 X159.160 Y147.140 E0.10685
G1 X158.951 Y147.046 E0.11047
G1 X158.752 Y146.931 E0.11409
G1 X158.566 Y146.797 E0.11771
G1 X158.394 Y146.646 E0.12134
G1 X158.238 Y146.477 E0.12496
G1 X158.100 Y146.295 E0.12858
G1 X157.980 Y146.099 E0.13220
G1 X157.881 Y145.893 E0.13582
G1 X157.802 Y145.677 E0.13944
G1 X157.746 Y145.455 E0.14307
G1 X157.712 Y145.228 E0.14669
G1 X157.700 Y144.999 E0.15031
G1 X157.712 Y144.770 E0.15393
G1 X157.746 Y144.544 E0.15756
G1 X157.802 Y144.321 E0.16118
G1 X157.880 Y144.108 E0.16476
G1 X158.039 Y143.798 E0.17027
G1 X158.167 Y143.611 E0.17385
G1 X158.314 Y143.435 E0.17747
G1 X158.478 Y143.275 E0.18110
G1 X158.658 Y143.132 E0.18472
G1 X158.850 Y143.008 E0.18834
G1 X159.054 Y142.903 E0.19196
G1 X159.268 Y142.819 E0.19558
G1 X159.488 Y142.757 E0.19921
G1 X159.714 Y142.717 E0.20283
G1 X159.943 Y142.700 E0.20645
G1 X160.172 Y142.706 E0.21007
G1 X160.399 Y142.734 E0.21370
G1 X160.623 Y142.785 E0.21732
G1 X160.840 Y142.858 E0.22094
G1 X161.049 Y142.953 E0.22456
G1 X161.248 Y143.067 E0.22818
; feature solid layer
G1 X159.317 Y144.551 F18000
G92 E0.00000
G1 X159.552 Y144.316 E0.00525 F15120
G1 X159.591 Y144.291 E0.00599
G1 X159.664 Y144.254 E0.00728
G1 X159.739 Y144.224 E0.00856
G1 X159.818 Y144.202 E0.00986
G1 X159.898 Y144.188 E0.01114
G1 X159.979 Y144.182 E0.01243
G1 X160.061 Y144.184 E0.01372
G1 X160.142 Y144.194 E0.01501
G1 X160.222 Y144.212 E0.01630
G1 X159.213 Y145.220 E0.03883
G1 X159.218 Y145.240 E0.03915
G1 X159.246 Y145.317 E0.04044
G1 X159.282 Y145.390 E0.04173
G1 X159.324 Y145.460 E0.04302
G1 X159.373 Y145.525 E0.04431
G1 X159.422 Y145.577 E0.04544
G1 X160.578 Y144.421 E0.07127
G1 X160.626 Y144.473 E0.07239
G1 X160.676 Y144.538 E0.07368
G1 X160.718 Y144.608 E0.07497
G1 X160.754 Y144.682 E0.07626
G1 X160.782 Y144.758 E0.07754
G1 X160.787 Y144.778 E0.07787
G1 X159.778 Y145.787 E0.10040
G1 X159.858 Y145.805 E0.10169
G1 X159.939 Y145.815 E0.10298
G1 X160.020 Y145.817 E0.10426
G1 X160.102 Y145.811 E0.10555
G1 X160.182 Y145.797 E0.10684
G1 X160.261 Y145.775 E0.10813
G1 X160.336 Y145.745 E0.10942
G1 X160.409 Y145.708 E0.11070
G1 X160.449 Y145.682 E0.11146
G1 X160.683 Y145.448 E0.11668
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 5, Z = 0.7000
; feature inner perimeter
G1 Z0.7000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.972 Y143.901 E0.02853
G1 X160.082 Y143.904 E0.03027
G1 X160.171 Y143.915 E0.03167
G1 X160.377 Y143.969 E0.03505
G1 X160.451 Y143.998 E0.03629
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.107 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09339
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.962 Y143.501 E0.03894
G1 X160.112 Y143.505 E0.04130
G1 X160.246 Y143.521 E0.04344
G1 X160.501 Y143.588 E0.04761
G1 X160.616 Y143.633 E0.04955
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12037
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12509
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.953 Y143.101 E0.04935
G1 X160.142 Y143.105 E0.05234
G1 X160.321 Y143.128 E0.05520
G1 X160.625 Y143.207 E0.06016
G1 X160.781 Y143.268 E0.06280
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.943 Y142.700 E0.05976
G1 X160.172 Y142.706 E0.06338
G1 X160.396 Y142.734 E0.06696
G1 X160.749 Y142.825 E0.07272
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 6, Z = 0.8000
; feature inner perimeter
G1 Z0.8000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02076
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02422
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03633
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.924 Y144.782 E0.07438
G1 X158.951 Y144.676 E0.07611
G1 X158.982 Y144.589 E0.07756
G1 X159.073 Y144.412 E0.08070
G1 X159.125 Y144.336 E0.08216
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08735
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09427
G1 X159.863 Y143.909 E0.09599
G1 X159.972 Y143.901 E0.09772
G1 X160.082 Y143.904 E0.09946
G1 X160.170 Y143.915 E0.10086
G1 X160.379 Y143.969 E0.10427
G1 X160.451 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02361
G1 X161.482 Y145.223 E0.02597
G1 X161.452 Y145.369 E0.02833
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06374
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.531 Y144.702 E0.10150
G1 X158.568 Y144.557 E0.10386
G1 X158.615 Y144.429 E0.10603
G1 X158.728 Y144.208 E0.10995
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.962 Y143.501 E0.13336
G1 X160.112 Y143.505 E0.13573
G1 X160.246 Y143.521 E0.13785
G1 X160.503 Y143.588 E0.14206
G1 X160.616 Y143.633 E0.14397
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.138 Y144.623 E0.12862
G1 X158.185 Y144.439 E0.13162
G1 X158.247 Y144.269 E0.13449
G1 X158.384 Y144.003 E0.13921
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14508
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15106
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.953 Y143.101 E0.16900
G1 X160.142 Y143.105 E0.17200
G1 X160.321 Y143.128 E0.17485
G1 X160.628 Y143.207 E0.17985
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.746 Y144.544 E0.15575
G1 X157.802 Y144.321 E0.15937
G1 X157.880 Y144.108 E0.16295
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17205
G1 X158.314 Y143.435 E0.17567
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19016
G1 X159.268 Y142.819 E0.19378
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.943 Y142.700 E0.20464
G1 X160.172 Y142.706 E0.20827
G1 X160.396 Y142.734 E0.21184
G1 X160.752 Y142.826 E0.21764
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.217 Y144.217 E0.10027
G1 X160.117 Y144.191 E0.10190
G1 X160.061 Y144.184 E0.10279
G1 X159.979 Y144.182 E0.10408
G1 X159.898 Y144.188 E0.10537
G1 X159.818 Y144.202 E0.10666
G1 X159.739 Y144.224 E0.10795
G1 X159.664 Y144.254 E0.10923
G1 X159.591 Y144.291 E0.11052
G1 X159.552 Y144.316 E0.11126
G1 X159.317 Y144.551 E0.11651
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 7, Z = 0.9000
; feature inner perimeter
G1 Z0.9000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.920 Y144.803 E0.00485
G1 X158.981 Y144.593 E0.00830
G1 X159.010 Y144.524 E0.00948
G1 X159.063 Y144.427 E0.01123
G1 X159.124 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09339
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.529 Y144.717 E0.00684
G1 X158.603 Y144.459 E0.01109
G1 X158.649 Y144.350 E0.01296
G1 X158.721 Y144.218 E0.01534
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12037
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12509
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.137 Y144.632 E0.00883
G1 X158.225 Y144.325 E0.01387
G1 X158.288 Y144.176 E0.01643
G1 X158.379 Y144.009 E0.01944
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.745 Y144.547 E0.01082
G1 X157.847 Y144.191 E0.01666
G1 X157.928 Y144.002 E0.01991
G1 X158.038 Y143.800 E0.02354
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01408
G1 X159.195 Y144.862 E0.01497
G1 X159.217 Y144.782 E0.01629
G1 X160.221 Y145.786 E0.03870
G1 X160.261 Y145.775 E0.03935
G1 X160.336 Y145.745 E0.04064
G1 X160.409 Y145.708 E0.04193
G1 X160.477 Y145.663 E0.04322
G1 X160.541 Y145.612 E0.04451
G1 X160.578 Y145.577 E0.04531
G1 X159.422 Y144.422 E0.07112
G1 X159.459 Y144.386 E0.07193
G1 X159.523 Y144.335 E0.07322
G1 X159.591 Y144.291 E0.07450
G1 X159.664 Y144.254 E0.07580
G1 X159.739 Y144.224 E0.07708
G1 X159.779 Y144.213 E0.07773
G1 X160.787 Y145.220 E0.10024
G1 X160.793 Y145.201 E0.10056
G1 X160.809 Y145.121 E0.10185
G1 X160.817 Y145.040 E0.10314
G1 X160.817 Y144.958 E0.10443
G1 X160.809 Y144.877 E0.10571
G1 X160.793 Y144.797 E0.10700
G1 X160.769 Y144.719 E0.10829
G1 X160.737 Y144.644 E0.10958
G1 X160.698 Y144.573 E0.11087
G1 X160.683 Y144.551 E0.11128
G1 X160.449 Y144.316 E0.11652
G92 E0.00000
G1 E-0.50000 F2400
; layer 8, Z = 1.0000
; feature inner perimeter
G1 Z1.0000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02076
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02422
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02768
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03633
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.924 Y144.782 E0.07438
G1 X158.951 Y144.676 E0.07611
G1 X158.982 Y144.589 E0.07756
G1 X159.073 Y144.412 E0.08070
G1 X159.125 Y144.336 E0.08216
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08735
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09427
G1 X159.863 Y143.909 E0.09599
G1 X159.972 Y143.901 E0.09772
G1 X160.082 Y143.904 E0.09945
G1 X160.169 Y143.915 E0.10084
G1 X160.383 Y143.971 E0.10433
G1 X160.450 Y143.997 E0.10547
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01889
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02361
G1 X161.482 Y145.223 E0.02597
G1 X161.452 Y145.369 E0.02833
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06374
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07554
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.531 Y144.702 E0.10150
G1 X158.568 Y144.557 E0.10386
G1 X158.615 Y144.429 E0.10603
G1 X158.728 Y144.208 E0.10996
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12393
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.962 Y143.501 E0.13336
G1 X160.112 Y143.505 E0.13573
G1 X160.245 Y143.521 E0.13784
G1 X160.507 Y143.590 E0.14212
G1 X160.615 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.138 Y144.623 E0.12862
G1 X158.185 Y144.439 E0.13162
G1 X158.247 Y144.269 E0.13449
G1 X158.384 Y144.003 E0.13921
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14508
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15106
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.953 Y143.101 E0.16900
G1 X160.142 Y143.105 E0.17200
G1 X160.321 Y143.128 E0.17484
G1 X160.632 Y143.209 E0.17992
G1 X160.780 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.746 Y144.544 E0.15575
G1 X157.802 Y144.321 E0.15937
G1 X157.880 Y144.108 E0.16295
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17205
G1 X158.314 Y143.435 E0.17567
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19016
G1 X159.268 Y142.819 E0.19378
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.943 Y142.700 E0.20464
G1 X160.172 Y142.706 E0.20827
G1 X160.396 Y142.734 E0.21184
G1 X160.756 Y142.828 E0.21772
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.217 Y144.217 E0.10026
G1 X160.116 Y144.191 E0.10191
G1 X160.061 Y144.184 E0.10278
G1 X159.979 Y144.182 E0.10408
G1 X159.898 Y144.188 E0.10536
G1 X159.818 Y144.202 E0.10665
G1 X159.739 Y144.224 E0.10794
G1 X159.664 Y144.254 E0.10922
G1 X159.591 Y144.291 E0.11052
G1 X159.552 Y144.316 E0.11126
G1 X159.317 Y144.551 E0.11651
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 9, Z = 1.1000
; feature inner perimeter
G1 Z1.1000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09340
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12038
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12510
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 10, Z = 1.2000
; feature inner perimeter
G1 Z1.2000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.920 Y144.804 E0.07402
G1 X158.983 Y144.588 E0.07758
G1 X159.009 Y144.525 E0.07866
G1 X159.063 Y144.427 E0.08042
G1 X159.125 Y144.336 E0.08215
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08734
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09426
G1 X159.863 Y143.909 E0.09599
G1 X159.955 Y143.903 E0.09745
G1 X160.154 Y143.913 E0.10059
G1 X160.244 Y143.928 E0.10204
G1 X160.350 Y143.958 E0.10377
G1 X160.452 Y143.998 E0.10550
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.529 Y144.718 E0.10125
G1 X158.605 Y144.453 E0.10560
G1 X158.649 Y144.350 E0.10737
G1 X158.721 Y144.218 E0.10975
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.950 Y143.502 E0.13316
G1 X160.199 Y143.514 E0.13709
G1 X160.333 Y143.538 E0.13926
G1 X160.477 Y143.579 E0.14162
G1 X160.616 Y143.633 E0.14398
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.137 Y144.632 E0.12847
G1 X158.228 Y144.319 E0.13363
G1 X158.288 Y144.176 E0.13608
G1 X158.379 Y144.009 E0.13909
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14507
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15105
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.945 Y143.101 E0.16888
G1 X160.244 Y143.116 E0.17360
G1 X160.423 Y143.148 E0.17648
G1 X160.605 Y143.199 E0.17947
G1 X160.781 Y143.268 E0.18246
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.745 Y144.547 E0.15570
G1 X157.850 Y144.185 E0.16165
G1 X157.928 Y144.002 E0.16479
G1 X158.038 Y143.800 E0.16842
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19015
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.940 Y142.700 E0.20460
G1 X160.288 Y142.718 E0.21011
G1 X160.512 Y142.757 E0.21369
G1 X160.733 Y142.819 E0.21732
G1 X160.946 Y142.903 E0.22094
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.221 Y144.213 E0.10035
G1 X160.182 Y144.202 E0.10099
G1 X160.122 Y144.191 E0.10195
G1 X159.959 Y144.183 E0.10454
G1 X159.898 Y144.188 E0.10549
G1 X159.818 Y144.202 E0.10678
G1 X159.739 Y144.224 E0.10807
G1 X159.664 Y144.254 E0.10936
G1 X159.591 Y144.291 E0.11065
G1 X159.552 Y144.316 E0.11139
G1 X159.317 Y144.551 E0.11664
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 11, Z = 1.3000
; feature inner perimeter
G1 Z1.3000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09340
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12038
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12510
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 12, Z = 1.4000
; feature inner perimeter
G1 Z1.4000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.924 Y144.782 E0.07438
G1 X158.951 Y144.676 E0.07611
G1 X158.982 Y144.589 E0.07756
G1 X159.073 Y144.412 E0.08070
G1 X159.125 Y144.336 E0.08215
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08735
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09427
G1 X159.863 Y143.909 E0.09599
G1 X159.955 Y143.903 E0.09745
G1 X160.154 Y143.913 E0.10059
G1 X160.244 Y143.928 E0.10204
G1 X160.350 Y143.958 E0.10377
G1 X160.452 Y143.998 E0.10550
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.531 Y144.702 E0.10150
G1 X158.568 Y144.557 E0.10386
G1 X158.615 Y144.429 E0.10602
G1 X158.728 Y144.208 E0.10995
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.950 Y143.502 E0.13317
G1 X160.199 Y143.514 E0.13710
G1 X160.333 Y143.538 E0.13926
G1 X160.477 Y143.579 E0.14162
G1 X160.616 Y143.633 E0.14398
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.138 Y144.623 E0.12862
G1 X158.185 Y144.439 E0.13162
G1 X158.247 Y144.269 E0.13449
G1 X158.384 Y144.003 E0.13921
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14508
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15106
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.945 Y143.101 E0.16888
G1 X160.244 Y143.116 E0.17360
G1 X160.423 Y143.148 E0.17648
G1 X160.605 Y143.199 E0.17947
G1 X160.781 Y143.268 E0.18246
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.746 Y144.544 E0.15575
G1 X157.802 Y144.321 E0.15937
G1 X157.880 Y144.108 E0.16295
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17205
G1 X158.314 Y143.435 E0.17567
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19016
G1 X159.268 Y142.819 E0.19378
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.940 Y142.700 E0.20460
G1 X160.288 Y142.718 E0.21011
G1 X160.512 Y142.757 E0.21369
G1 X160.733 Y142.819 E0.21732
G1 X160.946 Y142.903 E0.22094
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.221 Y144.213 E0.10035
G1 X160.182 Y144.202 E0.10099
G1 X160.122 Y144.191 E0.10195
G1 X159.959 Y144.183 E0.10454
G1 X159.898 Y144.188 E0.10549
G1 X159.818 Y144.202 E0.10678
G1 X159.739 Y144.224 E0.10807
G1 X159.664 Y144.254 E0.10936
G1 X159.591 Y144.291 E0.11065
G1 X159.552 Y144.316 E0.11139
G1 X159.317 Y144.551 E0.11664
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 13, Z = 1.5000
; feature inner perimeter
G1 Z1.5000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.920 Y144.805 E0.00481
G1 X158.985 Y144.582 E0.00848
G1 X159.009 Y144.525 E0.00946
G1 X159.063 Y144.427 E0.01123
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02825
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06744
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07436
G1 X160.452 Y146.000 E0.07609
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08128
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08647
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09339
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.528 Y144.719 E0.00681
G1 X158.607 Y144.447 E0.01128
G1 X158.649 Y144.351 E0.01294
G1 X158.721 Y144.218 E0.01533
G1 X158.805 Y144.094 E0.01769
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08024
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11801
G1 X159.594 Y146.442 E0.12037
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12509
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12981
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.137 Y144.633 E0.00881
G1 X158.230 Y144.313 E0.01408
G1 X158.288 Y144.176 E0.01643
G1 X158.379 Y144.009 E0.01944
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04037
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05981
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08075
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10468
G1 X161.785 Y145.649 E0.10767
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12562
G1 X160.950 Y146.644 E0.12861
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14955
G1 X159.486 Y146.828 E0.15254
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17049
G1 X158.431 Y146.069 E0.17348
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.745 Y144.547 E0.01081
G1 X157.853 Y144.178 E0.01688
G1 X157.928 Y144.002 E0.01991
G1 X158.038 Y143.800 E0.02354
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11227
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14487
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18109
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01408
G1 X159.194 Y144.865 E0.01492
G1 X159.218 Y144.783 E0.01628
G1 X160.221 Y145.786 E0.03868
G1 X160.261 Y145.775 E0.03934
G1 X160.336 Y145.745 E0.04062
G1 X160.409 Y145.708 E0.04191
G1 X160.477 Y145.663 E0.04320
G1 X160.541 Y145.612 E0.04449
G1 X160.578 Y145.577 E0.04529
G1 X159.422 Y144.422 E0.07111
G1 X159.459 Y144.386 E0.07191
G1 X159.523 Y144.335 E0.07320
G1 X159.591 Y144.291 E0.07449
G1 X159.664 Y144.254 E0.07578
G1 X159.739 Y144.224 E0.07706
G1 X159.779 Y144.213 E0.07771
G1 X160.787 Y145.220 E0.10022
G1 X160.793 Y145.201 E0.10054
G1 X160.809 Y145.121 E0.10183
G1 X160.817 Y145.040 E0.10312
G1 X160.817 Y144.958 E0.10441
G1 X160.809 Y144.877 E0.10570
G1 X160.793 Y144.797 E0.10698
G1 X160.769 Y144.719 E0.10827
G1 X160.737 Y144.644 E0.10956
G1 X160.698 Y144.573 E0.11085
G1 X160.683 Y144.551 E0.11126
G1 X160.449 Y144.316 E0.11651
G92 E0.00000
G1 E-0.50000 F2400
; layer 14, Z = 1.6000
; feature inner perimeter
G1 Z1.6000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02076
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02422
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02768
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03633
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.924 Y144.782 E0.07438
G1 X158.951 Y144.676 E0.07611
G1 X158.982 Y144.589 E0.07756
G1 X159.073 Y144.412 E0.08070
G1 X159.125 Y144.336 E0.08216
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08735
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09427
G1 X159.863 Y143.909 E0.09599
G1 X159.972 Y143.901 E0.09772
G1 X160.082 Y143.904 E0.09946
G1 X160.167 Y143.915 E0.10081
G1 X160.393 Y143.975 E0.10450
G1 X160.449 Y143.997 E0.10545
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.531 Y144.702 E0.10150
G1 X158.568 Y144.557 E0.10386
G1 X158.615 Y144.429 E0.10602
G1 X158.728 Y144.208 E0.10995
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.962 Y143.501 E0.13336
G1 X160.112 Y143.505 E0.13573
G1 X160.243 Y143.521 E0.13781
G1 X160.519 Y143.594 E0.14232
G1 X160.614 Y143.632 E0.14394
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.138 Y144.623 E0.12862
G1 X158.185 Y144.439 E0.13162
G1 X158.247 Y144.269 E0.13449
G1 X158.384 Y144.003 E0.13921
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14508
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15106
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.953 Y143.101 E0.16900
G1 X160.142 Y143.105 E0.17200
G1 X160.320 Y143.128 E0.17482
G1 X160.644 Y143.213 E0.18013
G1 X160.780 Y143.267 E0.18243
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.746 Y144.544 E0.15575
G1 X157.802 Y144.321 E0.15937
G1 X157.880 Y144.108 E0.16295
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17205
G1 X158.314 Y143.435 E0.17567
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19016
G1 X159.268 Y142.819 E0.19378
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.943 Y142.700 E0.20464
G1 X160.172 Y142.706 E0.20827
G1 X160.396 Y142.734 E0.21183
G1 X160.770 Y142.833 E0.21794
G1 X160.945 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.216 Y144.217 E0.10025
G1 X160.113 Y144.190 E0.10193
G1 X160.061 Y144.184 E0.10276
G1 X159.979 Y144.182 E0.10406
G1 X159.898 Y144.188 E0.10534
G1 X159.818 Y144.202 E0.10663
G1 X159.739 Y144.224 E0.10792
G1 X159.664 Y144.254 E0.10920
G1 X159.591 Y144.291 E0.11050
G1 X159.552 Y144.316 E0.11123
G1 X159.317 Y144.551 E0.11648
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 15, Z = 1.7000
; feature inner perimeter
G1 Z1.7000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09340
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12038
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12510
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 16, Z = 1.8000
; feature inner perimeter
G1 Z1.8000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.920 Y144.806 E0.07399
G1 X158.987 Y144.577 E0.07776
G1 X159.009 Y144.526 E0.07864
G1 X159.063 Y144.427 E0.08042
G1 X159.125 Y144.336 E0.08215
G1 X159.195 Y144.252 E0.08388
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08734
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09080
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09426
G1 X159.863 Y143.909 E0.09599
G1 X159.955 Y143.903 E0.09744
G1 X160.154 Y143.913 E0.10059
G1 X160.244 Y143.928 E0.10204
G1 X160.350 Y143.958 E0.10377
G1 X160.452 Y143.998 E0.10550
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.528 Y144.720 E0.10122
G1 X158.610 Y144.442 E0.10580
G1 X158.648 Y144.351 E0.10735
G1 X158.721 Y144.218 E0.10975
G1 X158.805 Y144.094 E0.11211
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.950 Y143.502 E0.13316
G1 X160.199 Y143.514 E0.13709
G1 X160.333 Y143.538 E0.13926
G1 X160.477 Y143.579 E0.14162
G1 X160.616 Y143.633 E0.14398
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.137 Y144.633 E0.12846
G1 X158.232 Y144.307 E0.13384
G1 X158.288 Y144.176 E0.13607
G1 X158.379 Y144.009 E0.13909
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14507
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15105
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.945 Y143.101 E0.16888
G1 X160.244 Y143.116 E0.17360
G1 X160.423 Y143.148 E0.17647
G1 X160.605 Y143.199 E0.17947
G1 X160.781 Y143.268 E0.18246
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.745 Y144.547 E0.15569
G1 X157.855 Y144.171 E0.16188
G1 X157.928 Y144.002 E0.16479
G1 X158.038 Y143.800 E0.16842
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19015
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.940 Y142.700 E0.20460
G1 X160.288 Y142.718 E0.21011
G1 X160.512 Y142.757 E0.21369
G1 X160.733 Y142.819 E0.21732
G1 X160.946 Y142.903 E0.22094
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.221 Y144.213 E0.10035
G1 X160.182 Y144.202 E0.10099
G1 X160.122 Y144.191 E0.10195
G1 X159.959 Y144.183 E0.10454
G1 X159.898 Y144.188 E0.10549
G1 X159.818 Y144.202 E0.10678
G1 X159.739 Y144.224 E0.10807
G1 X159.664 Y144.254 E0.10936
G1 X159.591 Y144.291 E0.11065
G1 X159.552 Y144.316 E0.11139
G1 X159.317 Y144.551 E0.11664
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 17, Z = 1.9000
; feature inner perimeter
G1 Z1.9000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.920 Y144.807 E0.00479
G1 X158.987 Y144.576 E0.00859
G1 X159.009 Y144.526 E0.00944
G1 X159.063 Y144.427 E0.01123
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02161
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.972 Y143.901 E0.02853
G1 X160.082 Y143.904 E0.03026
G1 X160.191 Y143.918 E0.03199
G1 X160.297 Y143.942 E0.03372
G1 X160.401 Y143.977 E0.03545
G1 X160.501 Y144.022 E0.03718
G1 X160.596 Y144.077 E0.03891
G1 X160.685 Y144.141 E0.04064
G1 X160.767 Y144.213 E0.04237
G1 X160.841 Y144.293 E0.04410
G1 X160.907 Y144.380 E0.04583
G1 X160.965 Y144.474 E0.04756
G1 X161.012 Y144.573 E0.04929
G1 X161.049 Y144.675 E0.05102
G1 X161.076 Y144.782 E0.05275
G1 X161.093 Y144.894 E0.05454
G1 X161.096 Y144.947 E0.05538
G1 X161.081 Y145.188 E0.05919
G1 X161.064 Y145.270 E0.06052
G1 X161.032 Y145.375 E0.06225
G1 X160.990 Y145.476 E0.06398
G1 X160.937 Y145.572 E0.06571
G1 X160.875 Y145.662 E0.06744
G1 X160.805 Y145.746 E0.06917
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07436
G1 X160.452 Y146.000 E0.07609
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08128
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08647
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09339
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10376
G1 X158.951 Y145.323 E0.10549
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.528 Y144.720 E0.00680
G1 X158.610 Y144.440 E0.01141
G1 X158.648 Y144.351 E0.01293
G1 X158.721 Y144.218 E0.01533
G1 X158.805 Y144.094 E0.01769
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02241
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.962 Y143.501 E0.03894
G1 X160.112 Y143.505 E0.04130
G1 X160.260 Y143.523 E0.04366
G1 X160.406 Y143.557 E0.04602
G1 X160.548 Y143.604 E0.04838
G1 X160.684 Y143.666 E0.05074
G1 X160.813 Y143.740 E0.05310
G1 X160.934 Y143.827 E0.05546
G1 X161.047 Y143.926 E0.05783
G1 X161.148 Y144.036 E0.06018
G1 X161.238 Y144.155 E0.06254
G1 X161.316 Y144.283 E0.06491
G1 X161.381 Y144.417 E0.06727
G1 X161.432 Y144.557 E0.06963
G1 X161.469 Y144.702 E0.07199
G1 X161.492 Y144.853 E0.07439
G1 X161.497 Y144.949 E0.07591
G1 X161.478 Y145.240 E0.08053
G1 X161.452 Y145.369 E0.08260
G1 X161.408 Y145.512 E0.08496
G1 X161.350 Y145.649 E0.08732
G1 X161.279 Y145.781 E0.08968
G1 X161.195 Y145.904 E0.09204
G1 X161.099 Y146.019 E0.09440
G1 X160.992 Y146.123 E0.09676
G1 X160.875 Y146.216 E0.09912
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11801
G1 X159.594 Y146.442 E0.12037
G1 X159.452 Y146.394 E0.12273
G1 X159.316 Y146.333 E0.12509
G1 X159.187 Y146.258 E0.12745
G1 X159.066 Y146.171 E0.12981
G1 X158.954 Y146.072 E0.13217
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13689
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.137 Y144.634 E0.00880
G1 X158.233 Y144.305 E0.01422
G1 X158.288 Y144.177 E0.01642
G1 X158.379 Y144.009 E0.01943
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04037
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.953 Y143.101 E0.04935
G1 X160.142 Y143.105 E0.05234
G1 X160.330 Y143.129 E0.05533
G1 X160.514 Y143.171 E0.05832
G1 X160.694 Y143.231 E0.06131
G1 X160.866 Y143.309 E0.06431
G1 X161.030 Y143.404 E0.06730
G1 X161.184 Y143.514 E0.07029
G1 X161.326 Y143.640 E0.07328
G1 X161.455 Y143.778 E0.07627
G1 X161.569 Y143.929 E0.07926
G1 X161.668 Y144.091 E0.08226
G1 X161.750 Y144.261 E0.08524
G1 X161.815 Y144.439 E0.08824
G1 X161.862 Y144.623 E0.09123
G1 X161.890 Y144.812 E0.09425
G1 X161.898 Y144.950 E0.09644
G1 X161.876 Y145.293 E0.10186
G1 X161.840 Y145.468 E0.10468
G1 X161.785 Y145.649 E0.10767
G1 X161.711 Y145.823 E0.11066
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12562
G1 X160.950 Y146.644 E0.12861
G1 X160.781 Y146.730 E0.13160
G1 X160.605 Y146.800 E0.13459
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14955
G1 X159.486 Y146.828 E0.15254
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17049
G1 X158.431 Y146.069 E0.17348
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.745 Y144.547 E0.01081
G1 X157.856 Y144.169 E0.01703
G1 X157.928 Y144.002 E0.01991
G1 X158.038 Y143.800 E0.02354
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05251
G1 X159.714 Y142.717 E0.05614
G1 X159.943 Y142.700 E0.05976
G1 X160.172 Y142.706 E0.06338
G1 X160.399 Y142.734 E0.06700
G1 X160.623 Y142.785 E0.07062
G1 X160.840 Y142.858 E0.07425
G1 X161.049 Y142.953 E0.07787
G1 X161.248 Y143.067 E0.08149
G1 X161.434 Y143.201 E0.08511
G1 X161.606 Y143.353 E0.08874
G1 X161.762 Y143.521 E0.09236
G1 X161.900 Y143.704 E0.09598
G1 X162.020 Y143.899 E0.09960
G1 X162.119 Y144.106 E0.10322
G1 X162.198 Y144.321 E0.10685
G1 X162.254 Y144.544 E0.11047
G1 X162.288 Y144.771 E0.11410
G1 X162.299 Y144.952 E0.11697
G1 X162.273 Y145.346 E0.12320
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13038
G1 X162.072 Y145.997 E0.13400
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14487
G1 X161.522 Y146.723 E0.14849
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16660
G1 X160.286 Y147.281 E0.17022
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18109
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.194 Y144.867 E0.01490
G1 X159.218 Y144.783 E0.01628
G1 X160.221 Y145.786 E0.03867
G1 X160.261 Y145.775 E0.03932
G1 X160.336 Y145.745 E0.04061
G1 X160.409 Y145.708 E0.04190
G1 X160.477 Y145.663 E0.04319
G1 X160.541 Y145.612 E0.04448
G1 X160.578 Y145.577 E0.04528
G1 X159.422 Y144.422 E0.07109
G1 X159.459 Y144.386 E0.07190
G1 X159.523 Y144.335 E0.07319
G1 X159.591 Y144.291 E0.07448
G1 X159.664 Y144.254 E0.07577
G1 X159.739 Y144.224 E0.07705
G1 X159.779 Y144.213 E0.07770
G1 X160.787 Y145.220 E0.10021
G1 X160.793 Y145.201 E0.10053
G1 X160.803 Y145.151 E0.10134
G1 X160.816 Y144.946 E0.10458
G1 X160.815 Y144.923 E0.10496
G1 X160.802 Y144.837 E0.10632
G1 X160.782 Y144.758 E0.10761
G1 X160.754 Y144.682 E0.10889
G1 X160.718 Y144.608 E0.11018
G1 X160.684 Y144.552 E0.11122
G1 X160.445 Y144.313 E0.11655
G92 E0.00000
G1 E-0.50000 F2400
; layer 18, Z = 2.0000
; feature inner perimeter
G1 Z2.0000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.924 Y144.782 E0.07438
G1 X158.951 Y144.676 E0.07611
G1 X158.982 Y144.589 E0.07756
G1 X159.073 Y144.412 E0.08070
G1 X159.125 Y144.336 E0.08215
G1 X159.195 Y144.252 E0.08389
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08735
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09081
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09427
G1 X159.863 Y143.909 E0.09599
G1 X159.955 Y143.903 E0.09745
G1 X160.154 Y143.913 E0.10059
G1 X160.244 Y143.928 E0.10204
G1 X160.350 Y143.958 E0.10377
G1 X160.452 Y143.998 E0.10550
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.531 Y144.702 E0.10150
G1 X158.568 Y144.557 E0.10386
G1 X158.615 Y144.429 E0.10602
G1 X158.728 Y144.208 E0.10995
G1 X158.805 Y144.094 E0.11212
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11684
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.950 Y143.502 E0.13317
G1 X160.199 Y143.514 E0.13710
G1 X160.333 Y143.538 E0.13926
G1 X160.477 Y143.579 E0.14162
G1 X160.616 Y143.633 E0.14398
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.138 Y144.623 E0.12862
G1 X158.185 Y144.439 E0.13162
G1 X158.247 Y144.269 E0.13449
G1 X158.384 Y144.003 E0.13921
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14508
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15106
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16003
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.945 Y143.101 E0.16888
G1 X160.244 Y143.116 E0.17360
G1 X160.423 Y143.148 E0.17648
G1 X160.605 Y143.199 E0.17947
G1 X160.781 Y143.268 E0.18246
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.746 Y144.544 E0.15575
G1 X157.802 Y144.321 E0.15937
G1 X157.880 Y144.108 E0.16295
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17205
G1 X158.314 Y143.435 E0.17567
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19016
G1 X159.268 Y142.819 E0.19378
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.940 Y142.700 E0.20460
G1 X160.288 Y142.718 E0.21011
G1 X160.512 Y142.757 E0.21369
G1 X160.733 Y142.819 E0.21732
G1 X160.946 Y142.903 E0.22094
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.221 Y144.213 E0.10035
G1 X160.182 Y144.202 E0.10099
G1 X160.122 Y144.191 E0.10195
G1 X159.959 Y144.183 E0.10454
G1 X159.898 Y144.188 E0.10549
G1 X159.818 Y144.202 E0.10678
G1 X159.739 Y144.224 E0.10807
G1 X159.664 Y144.254 E0.10936
G1 X159.591 Y144.291 E0.11065
G1 X159.552 Y144.316 E0.11139
G1 X159.317 Y144.551 E0.11664
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 19, Z = 2.1000
; feature inner perimeter
G1 Z2.1000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.920 Y144.807 E0.00478
G1 X158.989 Y144.572 E0.00865
G1 X159.008 Y144.527 E0.00943
G1 X159.063 Y144.427 E0.01123
G1 X159.124 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02161
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02825
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05014
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05533
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05879
G1 X161.064 Y145.270 E0.06052
G1 X161.032 Y145.375 E0.06225
G1 X160.990 Y145.476 E0.06398
G1 X160.937 Y145.572 E0.06571
G1 X160.875 Y145.662 E0.06744
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07436
G1 X160.452 Y146.000 E0.07609
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08128
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08647
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09339
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.528 Y144.721 E0.00679
G1 X158.612 Y144.436 E0.01147
G1 X158.648 Y144.352 E0.01292
G1 X158.721 Y144.218 E0.01533
G1 X158.805 Y144.094 E0.01769
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02241
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07788
G1 X161.482 Y145.223 E0.08024
G1 X161.452 Y145.369 E0.08260
G1 X161.408 Y145.512 E0.08496
G1 X161.350 Y145.649 E0.08732
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11801
G1 X159.594 Y146.442 E0.12037
G1 X159.452 Y146.394 E0.12273
G1 X159.316 Y146.333 E0.12509
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12981
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.137 Y144.634 E0.00880
G1 X158.235 Y144.300 E0.01429
G1 X158.288 Y144.177 E0.01641
G1 X158.379 Y144.009 E0.01944
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04037
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05981
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08075
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10468
G1 X161.785 Y145.649 E0.10767
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12562
G1 X160.950 Y146.644 E0.12861
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14955
G1 X159.486 Y146.828 E0.15254
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17049
G1 X158.431 Y146.069 E0.17348
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.745 Y144.547 E0.01081
G1 X157.858 Y144.165 E0.01711
G1 X157.928 Y144.002 E0.01991
G1 X158.038 Y143.800 E0.02354
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05251
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09416
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11227
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13038
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14487
G1 X161.522 Y146.723 E0.14849
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18109
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.194 Y144.868 E0.01488
G1 X159.219 Y144.783 E0.01627
G1 X160.221 Y145.786 E0.03867
G1 X160.261 Y145.775 E0.03932
G1 X160.336 Y145.745 E0.04061
G1 X160.409 Y145.708 E0.04189
G1 X160.477 Y145.663 E0.04318
G1 X160.541 Y145.612 E0.04447
G1 X160.578 Y145.577 E0.04528
G1 X159.422 Y144.422 E0.07109
G1 X159.459 Y144.386 E0.07189
G1 X159.523 Y144.335 E0.07318
G1 X159.591 Y144.291 E0.07447
G1 X159.664 Y144.254 E0.07576
G1 X159.739 Y144.224 E0.07705
G1 X159.779 Y144.213 E0.07770
G1 X160.787 Y145.220 E0.10021
G1 X160.793 Y145.201 E0.10053
G1 X160.809 Y145.121 E0.10181
G1 X160.817 Y145.040 E0.10310
G1 X160.817 Y144.958 E0.10439
G1 X160.809 Y144.877 E0.10568
G1 X160.793 Y144.797 E0.10697
G1 X160.769 Y144.719 E0.10826
G1 X160.737 Y144.644 E0.10954
G1 X160.698 Y144.573 E0.11083
G1 X160.683 Y144.551 E0.11125
G1 X160.449 Y144.316 E0.11649
G92 E0.00000
G1 E-0.50000 F2400
; layer 20, Z = 2.2000
; feature inner perimeter
G1 Z2.2000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.027 Y146.097 E0.04324
G1 X159.918 Y146.094 E0.04497
G1 X159.809 Y146.081 E0.04670
G1 X159.703 Y146.056 E0.04843
G1 X159.599 Y146.022 E0.05016
G1 X159.499 Y145.977 E0.05189
G1 X159.404 Y145.922 E0.05362
G1 X159.315 Y145.858 E0.05535
G1 X159.233 Y145.785 E0.05708
G1 X159.159 Y145.705 E0.05881
G1 X159.093 Y145.618 E0.06054
G1 X159.035 Y145.524 E0.06227
G1 X158.988 Y145.426 E0.06400
G1 X158.951 Y145.323 E0.06573
G1 X158.923 Y145.217 E0.06746
G1 X158.907 Y145.109 E0.06919
G1 X158.902 Y144.999 E0.07092
G1 X158.907 Y144.890 E0.07265
G1 X158.920 Y144.808 E0.07396
G1 X158.990 Y144.570 E0.07787
G1 X159.008 Y144.527 E0.07862
G1 X159.063 Y144.427 E0.08042
G1 X159.125 Y144.336 E0.08215
G1 X159.195 Y144.252 E0.08388
G1 X159.273 Y144.176 E0.08561
G1 X159.359 Y144.107 E0.08734
G1 X159.451 Y144.048 E0.08907
G1 X159.548 Y143.998 E0.09080
G1 X159.650 Y143.958 E0.09253
G1 X159.756 Y143.928 E0.09426
G1 X159.863 Y143.909 E0.09599
G1 X159.955 Y143.903 E0.09744
G1 X160.154 Y143.913 E0.10059
G1 X160.244 Y143.928 E0.10204
G1 X160.350 Y143.958 E0.10377
G1 X160.452 Y143.998 E0.10550
G1 X160.549 Y144.048 E0.10723
G1 X160.641 Y144.108 E0.10896
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.037 Y146.498 E0.05901
G1 X159.888 Y146.494 E0.06137
G1 X159.740 Y146.475 E0.06373
G1 X159.594 Y146.442 E0.06609
G1 X159.452 Y146.394 E0.06846
G1 X159.316 Y146.333 E0.07081
G1 X159.187 Y146.258 E0.07318
G1 X159.066 Y146.171 E0.07553
G1 X158.954 Y146.072 E0.07790
G1 X158.852 Y145.963 E0.08026
G1 X158.762 Y145.844 E0.08262
G1 X158.684 Y145.716 E0.08498
G1 X158.619 Y145.581 E0.08734
G1 X158.568 Y145.441 E0.08970
G1 X158.531 Y145.296 E0.09206
G1 X158.509 Y145.148 E0.09442
G1 X158.501 Y144.999 E0.09678
G1 X158.509 Y144.850 E0.09914
G1 X158.528 Y144.721 E0.10120
G1 X158.613 Y144.434 E0.10593
G1 X158.648 Y144.352 E0.10734
G1 X158.721 Y144.218 E0.10975
G1 X158.805 Y144.094 E0.11211
G1 X158.901 Y143.980 E0.11448
G1 X159.008 Y143.876 E0.11683
G1 X159.125 Y143.782 E0.11920
G1 X159.251 Y143.701 E0.12156
G1 X159.384 Y143.633 E0.12392
G1 X159.523 Y143.579 E0.12628
G1 X159.667 Y143.538 E0.12864
G1 X159.814 Y143.512 E0.13100
G1 X159.950 Y143.502 E0.13316
G1 X160.199 Y143.514 E0.13709
G1 X160.333 Y143.538 E0.13926
G1 X160.477 Y143.579 E0.14162
G1 X160.616 Y143.633 E0.14398
G1 X160.749 Y143.701 E0.14634
G1 X160.875 Y143.782 E0.14870
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.047 Y146.898 E0.07478
G1 X159.858 Y146.893 E0.07777
G1 X159.670 Y146.870 E0.08077
G1 X159.486 Y146.828 E0.08375
G1 X159.306 Y146.767 E0.08675
G1 X159.134 Y146.689 E0.08974
G1 X158.970 Y146.595 E0.09273
G1 X158.816 Y146.484 E0.09572
G1 X158.674 Y146.359 E0.09871
G1 X158.545 Y146.220 E0.10170
G1 X158.431 Y146.069 E0.10469
G1 X158.332 Y145.907 E0.10769
G1 X158.250 Y145.737 E0.11068
G1 X158.185 Y145.559 E0.11367
G1 X158.138 Y145.376 E0.11666
G1 X158.110 Y145.188 E0.11965
G1 X158.101 Y144.999 E0.12264
G1 X158.110 Y144.810 E0.12563
G1 X158.137 Y144.634 E0.12845
G1 X158.236 Y144.298 E0.13398
G1 X158.288 Y144.177 E0.13606
G1 X158.379 Y144.009 E0.13909
G1 X158.486 Y143.853 E0.14208
G1 X158.608 Y143.707 E0.14507
G1 X158.743 Y143.575 E0.14806
G1 X158.891 Y143.457 E0.15105
G1 X159.050 Y143.355 E0.15404
G1 X159.219 Y143.268 E0.15704
G1 X159.395 Y143.199 E0.16002
G1 X159.577 Y143.148 E0.16302
G1 X159.764 Y143.115 E0.16601
G1 X159.945 Y143.101 E0.16888
G1 X160.244 Y143.116 E0.17360
G1 X160.423 Y143.148 E0.17647
G1 X160.605 Y143.199 E0.17947
G1 X160.781 Y143.268 E0.18246
G1 X160.950 Y143.354 E0.18545
G1 X161.109 Y143.457 E0.18844
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.057 Y147.298 E0.09055
G1 X159.828 Y147.293 E0.09417
G1 X159.601 Y147.264 E0.09780
G1 X159.377 Y147.213 E0.10142
G1 X159.160 Y147.140 E0.10504
G1 X158.951 Y147.046 E0.10866
G1 X158.752 Y146.931 E0.11228
G1 X158.566 Y146.797 E0.11591
G1 X158.394 Y146.646 E0.11953
G1 X158.238 Y146.477 E0.12315
G1 X158.100 Y146.295 E0.12677
G1 X157.980 Y146.099 E0.13040
G1 X157.881 Y145.893 E0.13402
G1 X157.802 Y145.677 E0.13764
G1 X157.746 Y145.455 E0.14126
G1 X157.712 Y145.228 E0.14488
G1 X157.700 Y144.999 E0.14850
G1 X157.712 Y144.770 E0.15213
G1 X157.745 Y144.547 E0.15569
G1 X157.859 Y144.162 E0.16203
G1 X157.928 Y144.002 E0.16479
G1 X158.038 Y143.800 E0.16842
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17929
G1 X158.658 Y143.132 E0.18291
G1 X158.850 Y143.008 E0.18653
G1 X159.054 Y142.903 E0.19015
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19740
G1 X159.714 Y142.717 E0.20102
G1 X159.940 Y142.700 E0.20460
G1 X160.288 Y142.718 E0.21011
G1 X160.512 Y142.757 E0.21369
G1 X160.733 Y142.819 E0.21732
G1 X160.946 Y142.903 E0.22094
G1 X161.150 Y143.008 E0.22456
G1 X161.342 Y143.132 E0.22818
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.020 Y145.817 E0.01241
G1 X159.939 Y145.815 E0.01370
G1 X159.858 Y145.805 E0.01499
G1 X159.778 Y145.787 E0.01628
G1 X160.787 Y144.778 E0.03881
G1 X160.769 Y144.719 E0.03978
G1 X160.737 Y144.644 E0.04107
G1 X160.698 Y144.573 E0.04236
G1 X160.652 Y144.505 E0.04365
G1 X160.600 Y144.443 E0.04493
G1 X160.578 Y144.422 E0.04541
G1 X159.422 Y145.577 E0.07123
G1 X159.373 Y145.525 E0.07236
G1 X159.324 Y145.460 E0.07365
G1 X159.282 Y145.390 E0.07494
G1 X159.246 Y145.317 E0.07623
G1 X159.218 Y145.240 E0.07752
G1 X159.213 Y145.220 E0.07784
G1 X160.221 Y144.213 E0.10035
G1 X160.182 Y144.202 E0.10099
G1 X160.122 Y144.191 E0.10195
G1 X159.959 Y144.183 E0.10454
G1 X159.898 Y144.188 E0.10549
G1 X159.818 Y144.202 E0.10678
G1 X159.739 Y144.224 E0.10807
G1 X159.664 Y144.254 E0.10936
G1 X159.591 Y144.291 E0.11065
G1 X159.552 Y144.316 E0.11139
G1 X159.317 Y144.551 E0.11664
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 21, Z = 2.3000
; feature inner perimeter
G1 Z2.3000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.027 Y146.097 E0.08301
G1 X159.918 Y146.094 E0.08474
G1 X159.809 Y146.081 E0.08648
G1 X159.703 Y146.056 E0.08820
G1 X159.599 Y146.022 E0.08993
G1 X159.499 Y145.977 E0.09166
G1 X159.404 Y145.922 E0.09340
G1 X159.315 Y145.858 E0.09512
G1 X159.233 Y145.785 E0.09685
G1 X159.159 Y145.705 E0.09858
G1 X159.093 Y145.618 E0.10031
G1 X159.035 Y145.524 E0.10204
G1 X158.988 Y145.426 E0.10377
G1 X158.951 Y145.323 E0.10550
G1 X158.923 Y145.217 E0.10723
G1 X158.907 Y145.109 E0.10896
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.037 Y146.498 E0.11329
G1 X159.888 Y146.494 E0.11565
G1 X159.740 Y146.475 E0.11802
G1 X159.594 Y146.442 E0.12038
G1 X159.452 Y146.394 E0.12274
G1 X159.316 Y146.333 E0.12510
G1 X159.187 Y146.258 E0.12746
G1 X159.066 Y146.171 E0.12982
G1 X158.954 Y146.072 E0.13218
G1 X158.852 Y145.963 E0.13454
G1 X158.762 Y145.844 E0.13690
G1 X158.684 Y145.716 E0.13926
G1 X158.619 Y145.581 E0.14162
G1 X158.568 Y145.441 E0.14398
G1 X158.531 Y145.296 E0.14634
G1 X158.509 Y145.148 E0.14870
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.047 Y146.898 E0.14357
G1 X159.858 Y146.893 E0.14656
G1 X159.670 Y146.870 E0.14956
G1 X159.486 Y146.828 E0.15255
G1 X159.306 Y146.767 E0.15554
G1 X159.134 Y146.689 E0.15853
G1 X158.970 Y146.595 E0.16152
G1 X158.816 Y146.484 E0.16451
G1 X158.674 Y146.359 E0.16750
G1 X158.545 Y146.220 E0.17050
G1 X158.431 Y146.069 E0.17349
G1 X158.332 Y145.907 E0.17648
G1 X158.250 Y145.737 E0.17947
G1 X158.185 Y145.559 E0.18246
G1 X158.138 Y145.376 E0.18545
G1 X158.110 Y145.188 E0.18844
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.057 Y147.298 E0.17385
G1 X159.828 Y147.293 E0.17747
G1 X159.601 Y147.264 E0.18110
G1 X159.377 Y147.213 E0.18472
G1 X159.160 Y147.140 E0.18834
G1 X158.951 Y147.046 E0.19196
G1 X158.752 Y146.931 E0.19558
G1 X158.566 Y146.797 E0.19921
G1 X158.394 Y146.646 E0.20283
G1 X158.238 Y146.477 E0.20645
G1 X158.100 Y146.295 E0.21007
G1 X157.980 Y146.099 E0.21370
G1 X157.881 Y145.893 E0.21732
G1 X157.802 Y145.677 E0.22094
G1 X157.746 Y145.455 E0.22456
G1 X157.712 Y145.228 E0.22818
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 22, Z = 2.4000
; feature inner perimeter
G1 Z2.4000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.919 Y144.808 E0.07393
G1 X158.981 Y144.602 E0.07733
G1 X159.079 Y144.404 E0.08083
G1 X159.125 Y144.336 E0.08212
G1 X159.195 Y144.252 E0.08385
G1 X159.273 Y144.176 E0.08558
G1 X159.359 Y144.107 E0.08731
G1 X159.451 Y144.048 E0.08904
G1 X159.548 Y143.998 E0.09077
G1 X159.650 Y143.958 E0.09250
G1 X159.756 Y143.928 E0.09423
G1 X159.863 Y143.909 E0.09596
G1 X159.955 Y143.903 E0.09741
G1 X160.154 Y143.913 E0.10055
G1 X160.244 Y143.928 E0.10201
G1 X160.350 Y143.958 E0.10374
G1 X160.452 Y143.998 E0.10547
G1 X160.549 Y144.048 E0.10720
G1 X160.641 Y144.108 E0.10893
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.528 Y144.721 E0.10118
G1 X158.607 Y144.456 E0.10556
G1 X158.732 Y144.201 E0.11004
G1 X158.805 Y144.094 E0.11209
G1 X158.901 Y143.980 E0.11445
G1 X159.008 Y143.876 E0.11681
G1 X159.125 Y143.782 E0.11917
G1 X159.251 Y143.701 E0.12153
G1 X159.384 Y143.633 E0.12389
G1 X159.523 Y143.579 E0.12625
G1 X159.667 Y143.538 E0.12861
G1 X159.814 Y143.512 E0.13097
G1 X159.950 Y143.502 E0.13313
G1 X160.199 Y143.514 E0.13707
G1 X160.333 Y143.538 E0.13923
G1 X160.477 Y143.579 E0.14159
G1 X160.616 Y143.633 E0.14395
G1 X160.749 Y143.701 E0.14631
G1 X160.875 Y143.782 E0.14867
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.137 Y144.634 E0.12843
G1 X158.233 Y144.309 E0.13379
G1 X158.386 Y143.999 E0.13925
G1 X158.486 Y143.852 E0.14205
G1 X158.608 Y143.707 E0.14505
G1 X158.743 Y143.575 E0.14804
G1 X158.891 Y143.457 E0.15103
G1 X159.050 Y143.355 E0.15402
G1 X159.219 Y143.268 E0.15701
G1 X159.395 Y143.199 E0.16000
G1 X159.577 Y143.148 E0.16299
G1 X159.764 Y143.115 E0.16598
G1 X159.945 Y143.101 E0.16886
G1 X160.244 Y143.116 E0.17358
G1 X160.423 Y143.148 E0.17645
G1 X160.605 Y143.199 E0.17944
G1 X160.781 Y143.268 E0.18243
G1 X160.950 Y143.354 E0.18543
G1 X161.109 Y143.457 E0.18842
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9553
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.745 Y144.547 E0.15568
G1 X157.859 Y144.163 E0.16201
G1 X158.040 Y143.797 E0.16846
G1 X158.167 Y143.611 E0.17202
G1 X158.314 Y143.435 E0.17564
G1 X158.478 Y143.275 E0.17927
G1 X158.658 Y143.132 E0.18289
G1 X158.850 Y143.008 E0.18651
G1 X159.054 Y142.903 E0.19013
G1 X159.268 Y142.819 E0.19375
G1 X159.488 Y142.757 E0.19738
G1 X159.714 Y142.717 E0.20100
G1 X159.940 Y142.700 E0.20458
G1 X160.288 Y142.718 E0.21009
G1 X160.512 Y142.757 E0.21367
G1 X160.733 Y142.819 E0.21730
G1 X160.946 Y142.903 E0.22092
G1 X161.150 Y143.008 E0.22454
G1 X161.342 Y143.132 E0.22816
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.319 Y144.549 E0.11657
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F10584
G1 X148.900 Y156.100 E0.06951
G1 X148.900 Y153.900 E0.10427
G1 X151.100 Y153.900 E0.13903
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F10584
G1 X148.500 Y156.500 E0.09479
G1 X148.500 Y153.500 E0.14219
G1 X151.500 Y153.500 E0.18958
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F11491
G1 X148.100 Y156.900 E0.12007
G1 X148.100 Y153.100 E0.18010
G1 X151.900 Y153.100 E0.24014
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F12172
G1 X147.700 Y157.300 E0.14535
G1 X147.700 Y152.700 E0.21802
G1 X152.300 Y152.700 E0.29069
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X149.180 Y155.820 E0.08520
G1 X149.180 Y155.346 E0.09270
G1 X150.346 Y154.180 E0.11874
G1 X149.780 Y154.180 E0.12768
G1 X149.180 Y154.780 E0.14108
G1 X149.180 Y154.214 E0.15002
G1 X149.214 Y154.180 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y156.100 E0.03476 F10584
G1 X138.900 Y156.100 E0.06951
G1 X138.900 Y153.900 E0.10427
G1 X141.100 Y153.900 E0.13903
G1 X141.500 Y153.500 F18000
G92 E0.00000
G1 X141.500 Y156.500 E0.04740 F10584
G1 X138.500 Y156.500 E0.09479
G1 X138.500 Y153.500 E0.14219
G1 X141.500 Y153.500 E0.18958
G1 X141.900 Y153.100 F18000
G92 E0.00000
G1 X141.900 Y156.900 E0.06003 F11491
G1 X138.100 Y156.900 E0.12007
G1 X138.100 Y153.100 E0.18010
G1 X141.900 Y153.100 E0.24014
; feature outer perimeter
G1 X142.300 Y152.700 F18000
G92 E0.00000
G1 X142.300 Y157.300 E0.07267 F12172
G1 X137.700 Y157.300 E0.14535
G1 X137.700 Y152.700 E0.21802
G1 X142.300 Y152.700 E0.29069
; feature solid layer
G1 X140.786 Y155.820 F18000
G92 E0.00000
G1 X140.820 Y155.786 E0.00076 F15120
G1 X140.820 Y155.220 E0.00970
G1 X140.220 Y155.820 E0.02309
G1 X139.655 Y155.820 E0.03203
G1 X140.820 Y154.655 E0.05807
G1 X140.820 Y154.180 E0.06557
G1 X140.729 Y154.180 E0.06700
G1 X139.180 Y155.729 E0.10161
G1 X139.180 Y155.163 E0.11055
G1 X140.163 Y154.180 E0.13252
G1 X139.598 Y154.180 E0.14146
G1 X139.180 Y154.598 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature support
G1 X140.990 Y159.000 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.010 Y159.000 E0.12670 F15120
G1 X149.010 Y158.010 E0.14235
G1 X146.990 Y158.010 E0.17426
G1 X146.990 Y158.000 E0.17442
G1 X143.010 Y158.000 E0.23730
G1 X143.010 Y157.000 E0.25309
G1 X146.990 Y157.000 E0.31597
G1 X146.990 Y156.000 E0.33177
G1 X143.010 Y156.000 E0.39465
G1 X143.010 Y155.000 E0.41045
G1 X146.990 Y155.000 E0.47333
G1 X146.990 Y154.000 E0.48913
G1 X143.010 Y154.000 E0.55200
G1 X143.010 Y153.000 E0.56780
G1 X146.990 Y153.000 E0.63068
G1 X146.990 Y152.000 E0.64648
G1 X143.010 Y152.000 E0.70936
G1 X143.010 Y151.990 E0.70952
G1 X140.990 Y151.990 E0.74143
G1 X140.990 Y151.000 E0.75707
G1 X149.010 Y151.000 E0.88377
G92 E0.00000
G1 E-0.50000 F2400
; layer 23, Z = 2.5000
; feature inner perimeter
G1 Z2.5000 F2400
G1 X148.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.03476 F10584
G1 X151.100 Y156.100 E0.06951
G1 X148.900 Y156.100 E0.10427
G1 X148.900 Y153.900 E0.13903
G1 X148.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.04740 F10584
G1 X151.500 Y156.500 E0.09479
G1 X148.500 Y156.500 E0.14219
G1 X148.500 Y153.500 E0.18958
G1 X148.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.06003 F11491
G1 X151.900 Y156.900 E0.12007
G1 X148.100 Y156.900 E0.18010
G1 X148.100 Y153.100 E0.24014
; feature outer perimeter
G1 X147.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.07267 F12172
G1 X152.300 Y157.300 E0.14535
G1 X147.700 Y157.300 E0.21802
G1 X147.700 Y152.700 E0.29069
; feature solid layer
G1 X150.402 Y154.180 F18000
G92 E0.00000
G1 X150.820 Y154.598 E0.00933 F15120
G1 X150.820 Y155.163 E0.01827
G1 X149.837 Y154.180 E0.04023
G1 X149.271 Y154.180 E0.04917
G1 X150.820 Y155.729 E0.08378
G1 X150.820 Y155.820 E0.08522
G1 X150.345 Y155.820 E0.09271
G1 X149.180 Y154.655 E0.11875
G1 X149.180 Y155.220 E0.12769
G1 X149.780 Y155.820 E0.14109
G1 X149.214 Y155.820 E0.15003
G1 X149.180 Y155.786 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; feature inner perimeter
G1 X141.100 Y156.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y156.100 E0.03476 F10584
G1 X138.900 Y153.900 E0.06951
G1 X141.100 Y153.900 E0.10427
G1 X141.100 Y156.100 E0.13903
G1 X141.500 Y156.500 F18000
G92 E0.00000
G1 X138.500 Y156.500 E0.04740 F10584
G1 X138.500 Y153.500 E0.09479
G1 X141.500 Y153.500 E0.14219
G1 X141.500 Y156.500 E0.18958
G1 X141.900 Y156.900 F18000
G92 E0.00000
G1 X138.100 Y156.900 E0.06003 F11491
G1 X138.100 Y153.100 E0.12007
G1 X141.900 Y153.100 E0.18010
G1 X141.900 Y156.900 E0.24014
; feature outer perimeter
G1 X142.300 Y157.300 F18000
G92 E0.00000
G1 X137.700 Y157.300 E0.07267 F12172
G1 X137.700 Y152.700 E0.14535
G1 X142.300 Y152.700 E0.21802
G1 X142.300 Y157.300 E0.29069
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X140.820 Y155.346 E0.11875
G1 X140.820 Y154.780 E0.12768
G1 X140.220 Y154.180 E0.14109
G1 X140.786 Y154.180 E0.15002
G1 X140.820 Y154.214 E0.15079
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.919 Y144.809 E0.00476
G1 X158.981 Y144.600 E0.00819
G1 X159.078 Y144.404 E0.01165
G1 X159.125 Y144.336 E0.01295
G1 X159.195 Y144.252 E0.01468
G1 X159.273 Y144.176 E0.01640
G1 X159.359 Y144.107 E0.01814
G1 X159.451 Y144.048 E0.01986
G1 X159.548 Y143.998 E0.02160
G1 X159.650 Y143.958 E0.02332
G1 X159.756 Y143.928 E0.02506
G1 X159.863 Y143.909 E0.02678
G1 X159.955 Y143.903 E0.02824
G1 X160.154 Y143.913 E0.03138
G1 X160.244 Y143.928 E0.03283
G1 X160.350 Y143.958 E0.03456
G1 X160.452 Y143.998 E0.03629
G1 X160.549 Y144.048 E0.03802
G1 X160.641 Y144.108 E0.03975
G1 X160.727 Y144.176 E0.04148
G1 X160.805 Y144.252 E0.04321
G1 X160.875 Y144.336 E0.04494
G1 X160.937 Y144.427 E0.04667
G1 X160.990 Y144.523 E0.04840
G1 X161.032 Y144.623 E0.05013
G1 X161.064 Y144.728 E0.05186
G1 X161.086 Y144.836 E0.05359
G1 X161.097 Y144.944 E0.05532
G1 X161.097 Y145.054 E0.05705
G1 X161.086 Y145.163 E0.05878
G1 X161.064 Y145.270 E0.06051
G1 X161.032 Y145.375 E0.06224
G1 X160.990 Y145.476 E0.06397
G1 X160.937 Y145.572 E0.06570
G1 X160.875 Y145.662 E0.06743
G1 X160.805 Y145.746 E0.06916
G1 X160.727 Y145.823 E0.07089
G1 X160.641 Y145.891 E0.07262
G1 X160.549 Y145.950 E0.07435
G1 X160.452 Y146.000 E0.07608
G1 X160.350 Y146.040 E0.07781
G1 X160.244 Y146.070 E0.07954
G1 X160.136 Y146.089 E0.08127
G1 X160.062 Y146.095 E0.08244
G1 X159.775 Y146.073 E0.08699
G1 X159.703 Y146.056 E0.08817
G1 X159.599 Y146.022 E0.08990
G1 X159.499 Y145.977 E0.09163
G1 X159.404 Y145.922 E0.09336
G1 X159.315 Y145.858 E0.09509
G1 X159.233 Y145.785 E0.09682
G1 X159.159 Y145.705 E0.09855
G1 X159.093 Y145.618 E0.10028
G1 X159.035 Y145.524 E0.10201
G1 X158.988 Y145.426 E0.10373
G1 X158.951 Y145.323 E0.10547
G1 X158.923 Y145.217 E0.10720
G1 X158.907 Y145.109 E0.10893
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.528 Y144.722 E0.00677
G1 X158.607 Y144.454 E0.01119
G1 X158.732 Y144.201 E0.01563
G1 X158.805 Y144.094 E0.01768
G1 X158.901 Y143.980 E0.02005
G1 X159.008 Y143.876 E0.02240
G1 X159.125 Y143.782 E0.02476
G1 X159.251 Y143.701 E0.02712
G1 X159.384 Y143.633 E0.02949
G1 X159.523 Y143.579 E0.03184
G1 X159.667 Y143.538 E0.03421
G1 X159.814 Y143.512 E0.03657
G1 X159.950 Y143.502 E0.03873
G1 X160.199 Y143.514 E0.04266
G1 X160.333 Y143.538 E0.04482
G1 X160.477 Y143.579 E0.04718
G1 X160.616 Y143.633 E0.04954
G1 X160.749 Y143.701 E0.05190
G1 X160.875 Y143.782 E0.05427
G1 X160.992 Y143.876 E0.05663
G1 X161.099 Y143.980 E0.05899
G1 X161.195 Y144.094 E0.06135
G1 X161.279 Y144.218 E0.06371
G1 X161.350 Y144.349 E0.06607
G1 X161.408 Y144.487 E0.06843
G1 X161.452 Y144.629 E0.07079
G1 X161.482 Y144.776 E0.07315
G1 X161.497 Y144.924 E0.07551
G1 X161.497 Y145.074 E0.07787
G1 X161.482 Y145.223 E0.08023
G1 X161.452 Y145.369 E0.08259
G1 X161.408 Y145.512 E0.08495
G1 X161.350 Y145.649 E0.08731
G1 X161.279 Y145.781 E0.08967
G1 X161.195 Y145.904 E0.09203
G1 X161.099 Y146.019 E0.09439
G1 X160.992 Y146.123 E0.09675
G1 X160.875 Y146.216 E0.09911
G1 X160.749 Y146.297 E0.10148
G1 X160.616 Y146.365 E0.10384
G1 X160.477 Y146.420 E0.10620
G1 X160.333 Y146.460 E0.10856
G1 X160.186 Y146.486 E0.11092
G1 X160.062 Y146.496 E0.11288
G1 X159.715 Y146.470 E0.11838
G1 X159.594 Y146.442 E0.12034
G1 X159.452 Y146.394 E0.12271
G1 X159.316 Y146.333 E0.12506
G1 X159.187 Y146.258 E0.12743
G1 X159.066 Y146.171 E0.12979
G1 X158.954 Y146.072 E0.13215
G1 X158.852 Y145.963 E0.13451
G1 X158.762 Y145.844 E0.13687
G1 X158.684 Y145.716 E0.13923
G1 X158.619 Y145.581 E0.14159
G1 X158.568 Y145.441 E0.14395
G1 X158.531 Y145.296 E0.14631
G1 X158.509 Y145.148 E0.14867
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.137 Y144.634 E0.00879
G1 X158.234 Y144.307 E0.01418
G1 X158.386 Y143.999 E0.01961
G1 X158.486 Y143.853 E0.02241
G1 X158.608 Y143.707 E0.02541
G1 X158.743 Y143.575 E0.02840
G1 X158.891 Y143.457 E0.03139
G1 X159.050 Y143.355 E0.03438
G1 X159.219 Y143.268 E0.03737
G1 X159.395 Y143.199 E0.04036
G1 X159.577 Y143.148 E0.04336
G1 X159.764 Y143.115 E0.04635
G1 X159.945 Y143.101 E0.04922
G1 X160.244 Y143.116 E0.05394
G1 X160.423 Y143.148 E0.05681
G1 X160.605 Y143.199 E0.05980
G1 X160.781 Y143.268 E0.06279
G1 X160.950 Y143.354 E0.06579
G1 X161.109 Y143.457 E0.06878
G1 X161.257 Y143.575 E0.07177
G1 X161.392 Y143.707 E0.07476
G1 X161.514 Y143.852 E0.07775
G1 X161.621 Y144.009 E0.08074
G1 X161.711 Y144.175 E0.08373
G1 X161.785 Y144.350 E0.08673
G1 X161.841 Y144.531 E0.08972
G1 X161.878 Y144.716 E0.09271
G1 X161.897 Y144.905 E0.09570
G1 X161.897 Y145.094 E0.09869
G1 X161.878 Y145.282 E0.10168
G1 X161.841 Y145.468 E0.10467
G1 X161.785 Y145.649 E0.10766
G1 X161.711 Y145.823 E0.11066
G1 X161.621 Y145.990 E0.11365
G1 X161.514 Y146.146 E0.11664
G1 X161.392 Y146.291 E0.11963
G1 X161.257 Y146.423 E0.12262
G1 X161.109 Y146.541 E0.12561
G1 X160.950 Y146.644 E0.12860
G1 X160.781 Y146.730 E0.13159
G1 X160.605 Y146.800 E0.13459
G1 X160.423 Y146.851 E0.13758
G1 X160.236 Y146.884 E0.14057
G1 X160.062 Y146.897 E0.14332
G1 X159.656 Y146.866 E0.14977
G1 X159.486 Y146.828 E0.15252
G1 X159.306 Y146.767 E0.15551
G1 X159.134 Y146.689 E0.15850
G1 X158.970 Y146.595 E0.16150
G1 X158.816 Y146.484 E0.16448
G1 X158.674 Y146.359 E0.16748
G1 X158.545 Y146.220 E0.17047
G1 X158.431 Y146.069 E0.17346
G1 X158.332 Y145.907 E0.17645
G1 X158.250 Y145.737 E0.17944
G1 X158.185 Y145.559 E0.18243
G1 X158.138 Y145.376 E0.18543
G1 X158.110 Y145.188 E0.18842
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9553
G1 X157.712 Y144.770 E0.00724
G1 X157.745 Y144.547 E0.01080
G1 X157.860 Y144.161 E0.01718
G1 X158.040 Y143.797 E0.02359
G1 X158.167 Y143.611 E0.02715
G1 X158.314 Y143.435 E0.03077
G1 X158.478 Y143.275 E0.03439
G1 X158.658 Y143.132 E0.03802
G1 X158.850 Y143.008 E0.04164
G1 X159.054 Y142.903 E0.04526
G1 X159.268 Y142.819 E0.04888
G1 X159.488 Y142.757 E0.05251
G1 X159.714 Y142.717 E0.05613
G1 X159.940 Y142.700 E0.05971
G1 X160.288 Y142.718 E0.06522
G1 X160.512 Y142.757 E0.06880
G1 X160.733 Y142.819 E0.07242
G1 X160.946 Y142.903 E0.07604
G1 X161.150 Y143.008 E0.07967
G1 X161.342 Y143.132 E0.08329
G1 X161.522 Y143.275 E0.08691
G1 X161.686 Y143.435 E0.09053
G1 X161.833 Y143.611 E0.09416
G1 X161.962 Y143.800 E0.09778
G1 X162.072 Y144.001 E0.10140
G1 X162.161 Y144.213 E0.10502
G1 X162.229 Y144.432 E0.10864
G1 X162.274 Y144.656 E0.11226
G1 X162.297 Y144.885 E0.11589
G1 X162.297 Y145.114 E0.11951
G1 X162.274 Y145.342 E0.12313
G1 X162.229 Y145.567 E0.12675
G1 X162.161 Y145.786 E0.13038
G1 X162.072 Y145.997 E0.13400
G1 X161.962 Y146.198 E0.13762
G1 X161.833 Y146.388 E0.14124
G1 X161.686 Y146.563 E0.14486
G1 X161.522 Y146.723 E0.14849
G1 X161.342 Y146.867 E0.15211
G1 X161.150 Y146.991 E0.15573
G1 X160.946 Y147.095 E0.15935
G1 X160.733 Y147.179 E0.16297
G1 X160.512 Y147.241 E0.16660
G1 X160.286 Y147.281 E0.17022
G1 X160.062 Y147.298 E0.17376
G1 X159.596 Y147.263 E0.18115
G1 X159.377 Y147.213 E0.18470
G1 X159.160 Y147.140 E0.18832
G1 X158.951 Y147.046 E0.19194
G1 X158.752 Y146.931 E0.19556
G1 X158.566 Y146.797 E0.19919
G1 X158.394 Y146.646 E0.20281
G1 X158.238 Y146.477 E0.20643
G1 X158.100 Y146.295 E0.21005
G1 X157.980 Y146.099 E0.21367
G1 X157.881 Y145.893 E0.21730
G1 X157.802 Y145.677 E0.22092
G1 X157.746 Y145.455 E0.22454
G1 X157.712 Y145.228 E0.22816
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.193 Y144.870 E0.01486
G1 X159.219 Y144.784 E0.01627
G1 X160.221 Y145.786 E0.03865
G1 X160.261 Y145.775 E0.03931
G1 X160.336 Y145.745 E0.04060
G1 X160.409 Y145.708 E0.04188
G1 X160.477 Y145.663 E0.04317
G1 X160.541 Y145.612 E0.04446
G1 X160.578 Y145.577 E0.04526
G1 X159.422 Y144.422 E0.07108
G1 X159.459 Y144.386 E0.07188
G1 X159.523 Y144.335 E0.07317
G1 X159.591 Y144.291 E0.07446
G1 X159.664 Y144.254 E0.07575
G1 X159.739 Y144.224 E0.07703
G1 X159.779 Y144.213 E0.07769
G1 X160.787 Y145.220 E0.10020
G1 X160.793 Y145.201 E0.10052
G1 X160.809 Y145.121 E0.10180
G1 X160.817 Y145.040 E0.10309
G1 X160.817 Y144.958 E0.10438
G1 X160.809 Y144.877 E0.10567
G1 X160.793 Y144.797 E0.10696
G1 X160.769 Y144.719 E0.10825
G1 X160.737 Y144.644 E0.10953
G1 X160.698 Y144.573 E0.11082
G1 X160.683 Y144.551 E0.11124
G1 X160.449 Y144.316 E0.11648
G92 E0.00000
G1 E-0.50000 F2400
; layer 24, Z = 2.6000
; feature inner perimeter
G1 Z2.6000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.676 E0.07609
G1 X158.982 Y144.589 E0.07754
G1 X159.073 Y144.412 E0.08068
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08560
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09252
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10895
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.557 E0.10385
G1 X158.615 Y144.429 E0.10601
G1 X158.728 Y144.208 E0.10994
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11919
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12627
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14161
G1 X160.616 Y143.633 E0.14397
G1 X160.749 Y143.701 E0.14633
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13160
G1 X158.247 Y144.269 E0.13448
G1 X158.384 Y144.003 E0.13920
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16002
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17946
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.802 Y144.321 E0.15936
G1 X157.880 Y144.108 E0.16294
G1 X158.039 Y143.798 E0.16845
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 25, Z = 2.7000
; feature inner perimeter
G1 Z2.7000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09165
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09511
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 26, Z = 2.8000
; feature inner perimeter
G1 Z2.8000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.952 Y144.671 E0.07617
G1 X158.967 Y144.628 E0.07688
G1 X159.078 Y144.405 E0.08083
G1 X159.124 Y144.336 E0.08213
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08559
G1 X159.359 Y144.107 E0.08732
G1 X159.451 Y144.048 E0.08905
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09251
G1 X159.756 Y143.928 E0.09424
G1 X159.863 Y143.909 E0.09597
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10894
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.569 Y144.554 E0.10390
G1 X158.598 Y144.472 E0.10528
G1 X158.732 Y144.202 E0.11004
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11446
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11918
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12626
G1 X159.667 Y143.538 E0.12862
G1 X159.814 Y143.512 E0.13098
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14632
G1 X160.875 Y143.782 E0.14868
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.186 Y144.437 E0.13164
G1 X158.229 Y144.315 E0.13369
G1 X158.386 Y143.999 E0.13925
G1 X158.486 Y143.853 E0.14206
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15702
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18244
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.803 Y144.321 E0.15937
G1 X157.860 Y144.159 E0.16209
G1 X158.040 Y143.797 E0.16847
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17565
G1 X158.478 Y143.275 E0.17927
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19376
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21730
G1 X160.946 Y142.903 E0.22092
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.319 Y144.549 E0.11658
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 27, Z = 2.9000
; feature inner perimeter
G1 Z2.9000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09165
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09511
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 28, Z = 3.0000
; feature inner perimeter
G1 Z3.0000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.676 E0.07609
G1 X158.982 Y144.589 E0.07754
G1 X159.073 Y144.412 E0.08068
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08560
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09252
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10895
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.557 E0.10385
G1 X158.615 Y144.429 E0.10601
G1 X158.728 Y144.208 E0.10994
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11919
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12627
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14161
G1 X160.616 Y143.633 E0.14397
G1 X160.749 Y143.701 E0.14633
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13160
G1 X158.247 Y144.269 E0.13448
G1 X158.384 Y144.003 E0.13920
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16002
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17946
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.802 Y144.321 E0.15936
G1 X157.880 Y144.108 E0.16294
G1 X158.039 Y143.798 E0.16845
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 29, Z = 3.1000
; feature inner perimeter
G1 Z3.1000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.952 Y144.671 E0.00699
G1 X158.969 Y144.623 E0.00780
G1 X159.077 Y144.405 E0.01164
G1 X159.124 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01469
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02161
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02825
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05014
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06052
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06398
G1 X160.937 Y145.572 E0.06571
G1 X160.875 Y145.662 E0.06744
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07436
G1 X160.452 Y146.000 E0.07609
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08128
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08818
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09164
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09510
G1 X159.233 Y145.785 E0.09683
G1 X159.159 Y145.705 E0.09856
G1 X159.093 Y145.618 E0.10029
G1 X159.035 Y145.524 E0.10202
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10721
G1 X158.907 Y145.109 E0.10894
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.569 Y144.554 E0.00949
G1 X158.600 Y144.466 E0.01098
G1 X158.731 Y144.203 E0.01562
G1 X158.805 Y144.094 E0.01769
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02241
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07788
G1 X161.482 Y145.223 E0.08024
G1 X161.452 Y145.369 E0.08260
G1 X161.408 Y145.512 E0.08496
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11839
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13452
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13924
G1 X158.619 Y145.581 E0.14160
G1 X158.568 Y145.441 E0.14396
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.186 Y144.438 E0.01199
G1 X158.232 Y144.309 E0.01415
G1 X158.386 Y144.000 E0.01961
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04037
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05981
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08075
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10468
G1 X161.785 Y145.649 E0.10767
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12562
G1 X160.950 Y146.644 E0.12861
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14333
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15552
G1 X159.134 Y146.689 E0.15851
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17646
G1 X158.250 Y145.737 E0.17945
G1 X158.185 Y145.559 E0.18244
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.803 Y144.321 E0.01450
G1 X157.863 Y144.152 E0.01733
G1 X158.040 Y143.797 E0.02359
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05251
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09416
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11227
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14487
G1 X161.522 Y146.723 E0.14849
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19919
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21368
G1 X157.881 Y145.893 E0.21730
G1 X157.802 Y145.677 E0.22092
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 30, Z = 3.2000
; feature inner perimeter
G1 Z3.2000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.952 Y144.672 E0.07615
G1 X158.970 Y144.621 E0.07700
G1 X159.077 Y144.406 E0.08080
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08559
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08905
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09251
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09597
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10894
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.569 Y144.555 E0.10389
G1 X158.601 Y144.464 E0.10541
G1 X158.731 Y144.203 E0.11002
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11446
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11918
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12626
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13098
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14632
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.186 Y144.438 E0.13163
G1 X158.232 Y144.307 E0.13383
G1 X158.385 Y144.000 E0.13924
G1 X158.486 Y143.853 E0.14206
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15702
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18244
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.803 Y144.321 E0.15937
G1 X157.864 Y144.150 E0.16224
G1 X158.040 Y143.797 E0.16847
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17565
G1 X158.478 Y143.275 E0.17927
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19376
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.318 Y144.550 E0.11659
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 31, Z = 3.3000
; feature inner perimeter
G1 Z3.3000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09165
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09511
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 32, Z = 3.4000
; feature inner perimeter
G1 Z3.4000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.672 E0.07615
G1 X158.971 Y144.618 E0.07706
G1 X159.077 Y144.406 E0.08079
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08559
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08905
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09251
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09597
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10894
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.555 E0.10389
G1 X158.602 Y144.460 E0.10548
G1 X158.731 Y144.203 E0.11002
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11446
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11918
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12626
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13098
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14632
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.186 Y144.438 E0.13163
G1 X158.234 Y144.303 E0.13390
G1 X158.385 Y144.000 E0.13924
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15702
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18244
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.803 Y144.321 E0.15937
G1 X157.866 Y144.145 E0.16232
G1 X158.040 Y143.797 E0.16846
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17565
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19376
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.318 Y144.550 E0.11660
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 33, Z = 3.5000
; feature inner perimeter
G1 Z3.5000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.672 E0.00697
G1 X158.972 Y144.616 E0.00792
G1 X159.076 Y144.407 E0.01161
G1 X159.125 Y144.336 E0.01297
G1 X159.195 Y144.252 E0.01469
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02825
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06398
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06744
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07436
G1 X160.452 Y146.000 E0.07609
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08128
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08818
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09164
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09510
G1 X159.233 Y145.785 E0.09683
G1 X159.159 Y145.705 E0.09856
G1 X159.093 Y145.618 E0.10029
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10721
G1 X158.907 Y145.109 E0.10894
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.555 E0.00948
G1 X158.603 Y144.458 E0.01111
G1 X158.731 Y144.204 E0.01560
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07788
G1 X161.482 Y145.223 E0.08024
G1 X161.452 Y145.369 E0.08260
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11839
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13452
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14160
G1 X158.568 Y145.441 E0.14396
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.438 E0.01199
G1 X158.235 Y144.301 E0.01429
G1 X158.385 Y144.000 E0.01960
G1 X158.486 Y143.852 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04037
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05981
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08075
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10468
G1 X161.785 Y145.649 E0.10767
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12562
G1 X160.950 Y146.644 E0.12861
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14333
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15851
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17646
G1 X158.250 Y145.737 E0.17945
G1 X158.185 Y145.559 E0.18244
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.803 Y144.321 E0.01450
G1 X157.866 Y144.143 E0.01748
G1 X158.040 Y143.797 E0.02359
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11227
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14487
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21368
G1 X157.881 Y145.893 E0.21730
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07788
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 34, Z = 3.6000
; feature inner perimeter
G1 Z3.6000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.676 E0.07609
G1 X158.982 Y144.589 E0.07754
G1 X159.073 Y144.412 E0.08068
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08560
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09252
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10895
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.557 E0.10385
G1 X158.615 Y144.429 E0.10601
G1 X158.728 Y144.208 E0.10994
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11919
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12627
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14161
G1 X160.616 Y143.633 E0.14397
G1 X160.749 Y143.701 E0.14633
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13160
G1 X158.247 Y144.269 E0.13448
G1 X158.384 Y144.003 E0.13920
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16002
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17946
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.802 Y144.321 E0.15936
G1 X157.880 Y144.108 E0.16294
G1 X158.039 Y143.798 E0.16845
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 35, Z = 3.7000
; feature inner perimeter
G1 Z3.7000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.673 E0.00696
G1 X158.973 Y144.613 E0.00797
G1 X159.076 Y144.407 E0.01160
G1 X159.124 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06744
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07436
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08128
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08818
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09164
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09510
G1 X159.233 Y145.785 E0.09683
G1 X159.159 Y145.705 E0.09856
G1 X159.093 Y145.618 E0.10029
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10721
G1 X158.907 Y145.109 E0.10894
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.555 E0.00947
G1 X158.605 Y144.455 E0.01117
G1 X158.730 Y144.204 E0.01560
G1 X158.805 Y144.094 E0.01769
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08024
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11839
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13452
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14160
G1 X158.568 Y145.441 E0.14396
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.438 E0.01198
G1 X158.236 Y144.296 E0.01436
G1 X158.385 Y144.001 E0.01959
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04037
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05981
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08075
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10767
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12562
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14333
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15851
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17945
G1 X158.185 Y145.559 E0.18244
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.803 Y144.321 E0.01450
G1 X157.868 Y144.138 E0.01756
G1 X158.040 Y143.797 E0.02359
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11227
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14487
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21368
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07788
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 36, Z = 3.8000
; feature inner perimeter
G1 Z3.8000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.673 E0.07613
G1 X158.974 Y144.611 E0.07718
G1 X159.076 Y144.408 E0.08077
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08559
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08905
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09251
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09597
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10894
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.556 E0.10388
G1 X158.605 Y144.453 E0.10561
G1 X158.730 Y144.204 E0.11000
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11918
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12626
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14632
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.438 E0.13162
G1 X158.237 Y144.294 E0.13404
G1 X158.385 Y144.001 E0.13923
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18244
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.803 Y144.321 E0.15937
G1 X157.869 Y144.136 E0.16247
G1 X158.039 Y143.797 E0.16846
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17565
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19376
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11661
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 37, Z = 3.9000
; feature inner perimeter
G1 Z3.9000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09165
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09511
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 38, Z = 4.0000
; feature inner perimeter
G1 Z4.0000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.673 E0.07612
G1 X158.975 Y144.607 E0.07724
G1 X159.075 Y144.408 E0.08075
G1 X159.124 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08559
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09251
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10894
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.556 E0.10387
G1 X158.607 Y144.449 E0.10567
G1 X158.730 Y144.205 E0.10999
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11918
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12626
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14632
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13162
G1 X158.239 Y144.290 E0.13411
G1 X158.385 Y144.001 E0.13923
G1 X158.486 Y143.853 E0.14206
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.803 Y144.321 E0.15937
G1 X157.871 Y144.132 E0.16254
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17565
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19376
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 39, Z = 4.1000
; feature inner perimeter
G1 Z4.1000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09165
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09511
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 40, Z = 4.2000
; feature inner perimeter
G1 Z4.2000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.676 E0.07609
G1 X158.982 Y144.589 E0.07754
G1 X159.073 Y144.412 E0.08068
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08560
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09252
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10895
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.557 E0.10385
G1 X158.615 Y144.429 E0.10601
G1 X158.728 Y144.208 E0.10994
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11919
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12627
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14161
G1 X160.616 Y143.633 E0.14397
G1 X160.749 Y143.701 E0.14633
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13160
G1 X158.247 Y144.269 E0.13448
G1 X158.384 Y144.003 E0.13920
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16002
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17946
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.802 Y144.321 E0.15936
G1 X157.880 Y144.108 E0.16294
G1 X158.039 Y143.798 E0.16845
G1 X158.167 Y143.611 E0.17204
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 41, Z = 4.3000
; feature inner perimeter
G1 Z4.3000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.674 E0.00694
G1 X158.977 Y144.602 E0.00815
G1 X159.075 Y144.410 E0.01156
G1 X159.125 Y144.336 E0.01297
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01815
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02507
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07782
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08818
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09164
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09510
G1 X159.233 Y145.785 E0.09683
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10029
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10894
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00946
G1 X158.609 Y144.443 E0.01136
G1 X158.729 Y144.206 E0.01557
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04267
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07316
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13452
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14160
G1 X158.568 Y145.441 E0.14396
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.241 Y144.284 E0.01458
G1 X158.384 Y144.002 E0.01958
G1 X158.486 Y143.852 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05682
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10169
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14333
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17945
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.873 Y144.125 E0.01779
G1 X158.039 Y143.798 E0.02359
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03440
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07243
G1 X160.946 Y142.903 E0.07605
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10865
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21368
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 42, Z = 4.4000
; feature inner perimeter
G1 Z4.4000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.674 E0.07611
G1 X158.978 Y144.600 E0.07735
G1 X159.074 Y144.410 E0.08073
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08560
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09251
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10894
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.557 E0.10386
G1 X158.610 Y144.441 E0.10580
G1 X158.729 Y144.206 E0.10997
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11919
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12627
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14633
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13161
G1 X158.242 Y144.282 E0.13425
G1 X158.384 Y144.002 E0.13921
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.803 Y144.321 E0.15936
G1 X157.874 Y144.123 E0.16270
G1 X158.039 Y143.798 E0.16846
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17565
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19376
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 43, Z = 4.5000
; feature inner perimeter
G1 Z4.5000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.676 E0.00692
G1 X158.982 Y144.589 E0.00837
G1 X159.073 Y144.412 E0.01151
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07091
G1 X160.641 Y145.891 E0.07264
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07956
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09165
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09511
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00944
G1 X158.615 Y144.429 E0.01160
G1 X158.728 Y144.208 E0.01553
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03875
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06609
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07553
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13453
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14161
G1 X158.568 Y145.441 E0.14397
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.247 Y144.269 E0.01484
G1 X158.384 Y144.003 E0.01956
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03141
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.880 Y144.108 E0.01807
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12315
G1 X162.229 Y145.567 E0.12677
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16299
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 44, Z = 4.6000
; feature inner perimeter
G1 Z4.6000 F2400
G1 X160.641 Y144.108 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.727 Y144.176 E0.00173 F10584
G1 X160.805 Y144.252 E0.00346
G1 X160.875 Y144.336 E0.00519
G1 X160.937 Y144.427 E0.00692
G1 X160.990 Y144.523 E0.00865
G1 X161.032 Y144.623 E0.01038
G1 X161.064 Y144.728 E0.01211
G1 X161.086 Y144.836 E0.01384
G1 X161.097 Y144.944 E0.01557
G1 X161.097 Y145.054 E0.01730
G1 X161.086 Y145.163 E0.01903
G1 X161.064 Y145.270 E0.02075
G1 X161.032 Y145.375 E0.02249
G1 X160.990 Y145.476 E0.02421
G1 X160.937 Y145.572 E0.02595
G1 X160.875 Y145.662 E0.02767
G1 X160.805 Y145.746 E0.02941
G1 X160.727 Y145.823 E0.03113
G1 X160.641 Y145.891 E0.03286
G1 X160.549 Y145.950 E0.03459
G1 X160.452 Y146.000 E0.03632
G1 X160.350 Y146.040 E0.03805
G1 X160.244 Y146.070 E0.03978
G1 X160.136 Y146.089 E0.04151
G1 X160.062 Y146.095 E0.04269
G1 X159.775 Y146.073 E0.04724
G1 X159.703 Y146.056 E0.04841
G1 X159.599 Y146.022 E0.05015
G1 X159.499 Y145.977 E0.05187
G1 X159.404 Y145.922 E0.05361
G1 X159.315 Y145.858 E0.05533
G1 X159.233 Y145.785 E0.05706
G1 X159.159 Y145.705 E0.05879
G1 X159.093 Y145.618 E0.06052
G1 X159.035 Y145.524 E0.06225
G1 X158.988 Y145.426 E0.06398
G1 X158.951 Y145.323 E0.06571
G1 X158.923 Y145.217 E0.06744
G1 X158.907 Y145.109 E0.06917
G1 X158.902 Y144.999 E0.07090
G1 X158.907 Y144.890 E0.07263
G1 X158.924 Y144.782 E0.07436
G1 X158.951 Y144.675 E0.07611
G1 X158.979 Y144.597 E0.07741
G1 X159.074 Y144.410 E0.08072
G1 X159.125 Y144.336 E0.08214
G1 X159.195 Y144.252 E0.08387
G1 X159.273 Y144.176 E0.08560
G1 X159.359 Y144.107 E0.08733
G1 X159.451 Y144.048 E0.08906
G1 X159.548 Y143.998 E0.09079
G1 X159.650 Y143.958 E0.09252
G1 X159.756 Y143.928 E0.09425
G1 X159.863 Y143.909 E0.09598
G1 X159.955 Y143.903 E0.09743
G1 X160.154 Y143.913 E0.10057
G1 X160.244 Y143.928 E0.10202
G1 X160.350 Y143.958 E0.10375
G1 X160.452 Y143.998 E0.10548
G1 X160.549 Y144.048 E0.10721
G1 X160.641 Y144.108 E0.10895
G1 X160.875 Y143.782 F18000
G92 E0.00000
G1 X160.992 Y143.876 E0.00236 F10584
G1 X161.099 Y143.980 E0.00472
G1 X161.195 Y144.094 E0.00708
G1 X161.279 Y144.218 E0.00944
G1 X161.350 Y144.349 E0.01180
G1 X161.408 Y144.487 E0.01416
G1 X161.452 Y144.629 E0.01652
G1 X161.482 Y144.776 E0.01888
G1 X161.497 Y144.924 E0.02124
G1 X161.497 Y145.074 E0.02360
G1 X161.482 Y145.223 E0.02596
G1 X161.452 Y145.369 E0.02832
G1 X161.408 Y145.512 E0.03069
G1 X161.350 Y145.649 E0.03305
G1 X161.279 Y145.781 E0.03541
G1 X161.195 Y145.904 E0.03777
G1 X161.099 Y146.019 E0.04013
G1 X160.992 Y146.123 E0.04249
G1 X160.875 Y146.216 E0.04485
G1 X160.749 Y146.297 E0.04721
G1 X160.616 Y146.365 E0.04957
G1 X160.477 Y146.420 E0.05193
G1 X160.333 Y146.460 E0.05429
G1 X160.186 Y146.486 E0.05665
G1 X160.062 Y146.496 E0.05862
G1 X159.715 Y146.470 E0.06411
G1 X159.594 Y146.442 E0.06608
G1 X159.452 Y146.394 E0.06844
G1 X159.316 Y146.333 E0.07080
G1 X159.187 Y146.258 E0.07316
G1 X159.066 Y146.171 E0.07552
G1 X158.954 Y146.072 E0.07788
G1 X158.852 Y145.963 E0.08024
G1 X158.762 Y145.844 E0.08260
G1 X158.684 Y145.716 E0.08497
G1 X158.619 Y145.581 E0.08732
G1 X158.568 Y145.441 E0.08968
G1 X158.531 Y145.296 E0.09205
G1 X158.509 Y145.148 E0.09441
G1 X158.501 Y144.999 E0.09677
G1 X158.509 Y144.850 E0.09913
G1 X158.531 Y144.702 E0.10149
G1 X158.568 Y144.557 E0.10386
G1 X158.611 Y144.437 E0.10586
G1 X158.729 Y144.206 E0.10996
G1 X158.805 Y144.094 E0.11210
G1 X158.901 Y143.980 E0.11447
G1 X159.008 Y143.876 E0.11682
G1 X159.125 Y143.782 E0.11919
G1 X159.251 Y143.701 E0.12154
G1 X159.384 Y143.633 E0.12391
G1 X159.523 Y143.579 E0.12627
G1 X159.667 Y143.538 E0.12863
G1 X159.814 Y143.512 E0.13099
G1 X159.950 Y143.502 E0.13315
G1 X160.199 Y143.514 E0.13708
G1 X160.333 Y143.538 E0.13924
G1 X160.477 Y143.579 E0.14160
G1 X160.616 Y143.633 E0.14396
G1 X160.749 Y143.701 E0.14633
G1 X160.875 Y143.782 E0.14869
G1 X161.109 Y143.457 F18000
G92 E0.00000
G1 X161.257 Y143.575 E0.00299 F10584
G1 X161.392 Y143.707 E0.00598
G1 X161.514 Y143.852 E0.00897
G1 X161.621 Y144.009 E0.01196
G1 X161.711 Y144.175 E0.01496
G1 X161.785 Y144.350 E0.01795
G1 X161.841 Y144.531 E0.02094
G1 X161.878 Y144.716 E0.02393
G1 X161.897 Y144.905 E0.02692
G1 X161.897 Y145.094 E0.02991
G1 X161.878 Y145.282 E0.03290
G1 X161.841 Y145.468 E0.03590
G1 X161.785 Y145.649 E0.03888
G1 X161.711 Y145.823 E0.04188
G1 X161.621 Y145.990 E0.04487
G1 X161.514 Y146.146 E0.04786
G1 X161.392 Y146.291 E0.05085
G1 X161.257 Y146.423 E0.05384
G1 X161.109 Y146.541 E0.05683
G1 X160.950 Y146.644 E0.05983
G1 X160.781 Y146.730 E0.06282
G1 X160.605 Y146.800 E0.06581
G1 X160.423 Y146.851 E0.06880
G1 X160.236 Y146.884 E0.07179
G1 X160.062 Y146.897 E0.07454
G1 X159.656 Y146.866 E0.08099
G1 X159.486 Y146.828 E0.08374
G1 X159.306 Y146.767 E0.08674
G1 X159.134 Y146.689 E0.08972
G1 X158.970 Y146.595 E0.09272
G1 X158.816 Y146.484 E0.09571
G1 X158.674 Y146.359 E0.09870
G1 X158.545 Y146.220 E0.10169
G1 X158.431 Y146.069 E0.10468
G1 X158.332 Y145.907 E0.10767
G1 X158.250 Y145.737 E0.11066
G1 X158.185 Y145.559 E0.11365
G1 X158.138 Y145.376 E0.11665
G1 X158.110 Y145.188 E0.11964
G1 X158.101 Y144.999 E0.12263
G1 X158.110 Y144.810 E0.12562
G1 X158.138 Y144.623 E0.12861
G1 X158.185 Y144.439 E0.13161
G1 X158.244 Y144.278 E0.13432
G1 X158.384 Y144.002 E0.13921
G1 X158.486 Y143.853 E0.14207
G1 X158.608 Y143.707 E0.14506
G1 X158.743 Y143.575 E0.14805
G1 X158.891 Y143.457 E0.15104
G1 X159.050 Y143.355 E0.15403
G1 X159.219 Y143.268 E0.15703
G1 X159.395 Y143.199 E0.16001
G1 X159.577 Y143.148 E0.16301
G1 X159.764 Y143.115 E0.16600
G1 X159.945 Y143.101 E0.16887
G1 X160.244 Y143.116 E0.17359
G1 X160.423 Y143.148 E0.17646
G1 X160.605 Y143.199 E0.17945
G1 X160.781 Y143.268 E0.18245
G1 X160.950 Y143.354 E0.18544
G1 X161.109 Y143.457 E0.18843
; feature outer perimeter
G1 X161.342 Y143.132 F18000
G92 E0.00000
G1 X161.522 Y143.275 E0.00362 F9554
G1 X161.686 Y143.435 E0.00724
G1 X161.833 Y143.611 E0.01087
G1 X161.962 Y143.800 E0.01449
G1 X162.072 Y144.001 E0.01811
G1 X162.161 Y144.213 E0.02173
G1 X162.229 Y144.432 E0.02535
G1 X162.274 Y144.656 E0.02898
G1 X162.297 Y144.885 E0.03260
G1 X162.297 Y145.114 E0.03622
G1 X162.274 Y145.342 E0.03984
G1 X162.229 Y145.567 E0.04346
G1 X162.161 Y145.786 E0.04709
G1 X162.072 Y145.997 E0.05071
G1 X161.962 Y146.198 E0.05433
G1 X161.833 Y146.388 E0.05795
G1 X161.686 Y146.563 E0.06158
G1 X161.522 Y146.723 E0.06520
G1 X161.342 Y146.867 E0.06882
G1 X161.150 Y146.991 E0.07244
G1 X160.946 Y147.095 E0.07606
G1 X160.733 Y147.179 E0.07968
G1 X160.512 Y147.241 E0.08331
G1 X160.286 Y147.281 E0.08693
G1 X160.062 Y147.298 E0.09047
G1 X159.596 Y147.263 E0.09786
G1 X159.377 Y147.213 E0.10141
G1 X159.160 Y147.140 E0.10503
G1 X158.951 Y147.046 E0.10865
G1 X158.752 Y146.931 E0.11227
G1 X158.566 Y146.797 E0.11590
G1 X158.394 Y146.646 E0.11952
G1 X158.238 Y146.477 E0.12314
G1 X158.100 Y146.295 E0.12676
G1 X157.980 Y146.099 E0.13038
G1 X157.881 Y145.893 E0.13401
G1 X157.802 Y145.677 E0.13763
G1 X157.746 Y145.455 E0.14125
G1 X157.712 Y145.228 E0.14487
G1 X157.700 Y144.999 E0.14849
G1 X157.712 Y144.770 E0.15212
G1 X157.746 Y144.544 E0.15574
G1 X157.802 Y144.321 E0.15936
G1 X157.876 Y144.118 E0.16277
G1 X158.039 Y143.798 E0.16845
G1 X158.167 Y143.611 E0.17203
G1 X158.314 Y143.435 E0.17566
G1 X158.478 Y143.275 E0.17928
G1 X158.658 Y143.132 E0.18290
G1 X158.850 Y143.008 E0.18652
G1 X159.054 Y142.903 E0.19014
G1 X159.268 Y142.819 E0.19377
G1 X159.488 Y142.757 E0.19739
G1 X159.714 Y142.717 E0.20101
G1 X159.940 Y142.700 E0.20459
G1 X160.288 Y142.718 E0.21010
G1 X160.512 Y142.757 E0.21368
G1 X160.733 Y142.819 E0.21731
G1 X160.946 Y142.903 E0.22093
G1 X161.150 Y143.008 E0.22455
G1 X161.342 Y143.132 E0.22817
; feature solid layer
G1 X160.683 Y145.448 F18000
G92 E0.00000
G1 X160.449 Y145.682 E0.00522 F15120
G1 X160.409 Y145.708 E0.00597
G1 X160.336 Y145.745 E0.00726
G1 X160.261 Y145.775 E0.00855
G1 X160.182 Y145.797 E0.00984
G1 X160.102 Y145.811 E0.01113
G1 X160.062 Y145.814 E0.01175
G1 X159.817 Y145.795 E0.01564
G1 X159.778 Y145.787 E0.01626
G1 X160.787 Y144.778 E0.03879
G1 X160.769 Y144.719 E0.03976
G1 X160.737 Y144.644 E0.04105
G1 X160.698 Y144.573 E0.04234
G1 X160.652 Y144.505 E0.04363
G1 X160.600 Y144.443 E0.04491
G1 X160.578 Y144.422 E0.04540
G1 X159.422 Y145.577 E0.07122
G1 X159.373 Y145.525 E0.07235
G1 X159.324 Y145.460 E0.07364
G1 X159.282 Y145.390 E0.07492
G1 X159.246 Y145.317 E0.07621
G1 X159.218 Y145.240 E0.07750
G1 X159.213 Y145.220 E0.07782
G1 X160.221 Y144.213 E0.10034
G1 X160.182 Y144.202 E0.10098
G1 X160.122 Y144.191 E0.10193
G1 X159.959 Y144.183 E0.10452
G1 X159.898 Y144.188 E0.10548
G1 X159.818 Y144.202 E0.10676
G1 X159.739 Y144.224 E0.10806
G1 X159.664 Y144.254 E0.10934
G1 X159.591 Y144.291 E0.11063
G1 X159.552 Y144.316 E0.11137
G1 X159.317 Y144.551 E0.11662
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X141.100 Y146.100 E0.03476 F10584
G1 X138.900 Y146.100 E0.06951
G1 X138.900 Y143.900 E0.10427
G1 X141.100 Y143.900 E0.13903
G1 X141.500 Y143.500 F18000
G92 E0.00000
G1 X141.500 Y146.500 E0.04740 F10584
G1 X138.500 Y146.500 E0.09479
G1 X138.500 Y143.500 E0.14219
G1 X141.500 Y143.500 E0.18958
G1 X141.900 Y143.100 F18000
G92 E0.00000
G1 X141.900 Y146.900 E0.06003 F11491
G1 X138.100 Y146.900 E0.12007
G1 X138.100 Y143.100 E0.18010
G1 X141.900 Y143.100 E0.24014
; feature outer perimeter
G1 X142.300 Y142.700 F18000
G92 E0.00000
G1 X142.300 Y147.300 E0.07267 F12172
G1 X137.700 Y147.300 E0.14535
G1 X137.700 Y142.700 E0.21802
G1 X142.300 Y142.700 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 45, Z = 4.7000
; feature inner perimeter
G1 Z4.7000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.109 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00173 F10584
G1 X158.907 Y144.890 E0.00346
G1 X158.924 Y144.782 E0.00519
G1 X158.951 Y144.675 E0.00693
G1 X158.980 Y144.595 E0.00827
G1 X159.074 Y144.411 E0.01154
G1 X159.125 Y144.336 E0.01296
G1 X159.195 Y144.252 E0.01470
G1 X159.273 Y144.176 E0.01642
G1 X159.359 Y144.107 E0.01816
G1 X159.451 Y144.048 E0.01988
G1 X159.548 Y143.998 E0.02162
G1 X159.650 Y143.958 E0.02334
G1 X159.756 Y143.928 E0.02508
G1 X159.863 Y143.909 E0.02680
G1 X159.955 Y143.903 E0.02826
G1 X160.154 Y143.913 E0.03140
G1 X160.244 Y143.928 E0.03285
G1 X160.350 Y143.958 E0.03458
G1 X160.452 Y143.998 E0.03631
G1 X160.549 Y144.048 E0.03804
G1 X160.641 Y144.108 E0.03977
G1 X160.727 Y144.176 E0.04150
G1 X160.805 Y144.252 E0.04323
G1 X160.875 Y144.336 E0.04496
G1 X160.937 Y144.427 E0.04669
G1 X160.990 Y144.523 E0.04842
G1 X161.032 Y144.623 E0.05015
G1 X161.064 Y144.728 E0.05188
G1 X161.086 Y144.836 E0.05361
G1 X161.097 Y144.944 E0.05534
G1 X161.097 Y145.054 E0.05707
G1 X161.086 Y145.163 E0.05880
G1 X161.064 Y145.270 E0.06053
G1 X161.032 Y145.375 E0.06226
G1 X160.990 Y145.476 E0.06399
G1 X160.937 Y145.572 E0.06572
G1 X160.875 Y145.662 E0.06745
G1 X160.805 Y145.746 E0.06918
G1 X160.727 Y145.823 E0.07090
G1 X160.641 Y145.891 E0.07263
G1 X160.549 Y145.950 E0.07437
G1 X160.452 Y146.000 E0.07610
G1 X160.350 Y146.040 E0.07783
G1 X160.244 Y146.070 E0.07955
G1 X160.136 Y146.089 E0.08129
G1 X160.062 Y146.095 E0.08246
G1 X159.775 Y146.073 E0.08701
G1 X159.703 Y146.056 E0.08819
G1 X159.599 Y146.022 E0.08992
G1 X159.499 Y145.977 E0.09164
G1 X159.404 Y145.922 E0.09338
G1 X159.315 Y145.858 E0.09510
G1 X159.233 Y145.785 E0.09684
G1 X159.159 Y145.705 E0.09857
G1 X159.093 Y145.618 E0.10030
G1 X159.035 Y145.524 E0.10203
G1 X158.988 Y145.426 E0.10375
G1 X158.951 Y145.323 E0.10548
G1 X158.923 Y145.217 E0.10722
G1 X158.907 Y145.109 E0.10895
G1 X158.509 Y145.148 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00236 F10584
G1 X158.509 Y144.850 E0.00472
G1 X158.531 Y144.702 E0.00708
G1 X158.568 Y144.557 E0.00945
G1 X158.612 Y144.435 E0.01149
G1 X158.729 Y144.206 E0.01555
G1 X158.805 Y144.094 E0.01770
G1 X158.901 Y143.980 E0.02006
G1 X159.008 Y143.876 E0.02242
G1 X159.125 Y143.782 E0.02478
G1 X159.251 Y143.701 E0.02714
G1 X159.384 Y143.633 E0.02950
G1 X159.523 Y143.579 E0.03186
G1 X159.667 Y143.538 E0.03422
G1 X159.814 Y143.512 E0.03658
G1 X159.950 Y143.502 E0.03874
G1 X160.199 Y143.514 E0.04268
G1 X160.333 Y143.538 E0.04484
G1 X160.477 Y143.579 E0.04720
G1 X160.616 Y143.633 E0.04956
G1 X160.749 Y143.701 E0.05192
G1 X160.875 Y143.782 E0.05428
G1 X160.992 Y143.876 E0.05664
G1 X161.099 Y143.980 E0.05900
G1 X161.195 Y144.094 E0.06136
G1 X161.279 Y144.218 E0.06372
G1 X161.350 Y144.349 E0.06608
G1 X161.408 Y144.487 E0.06844
G1 X161.452 Y144.629 E0.07080
G1 X161.482 Y144.776 E0.07317
G1 X161.497 Y144.924 E0.07552
G1 X161.497 Y145.074 E0.07789
G1 X161.482 Y145.223 E0.08025
G1 X161.452 Y145.369 E0.08261
G1 X161.408 Y145.512 E0.08497
G1 X161.350 Y145.649 E0.08733
G1 X161.279 Y145.781 E0.08969
G1 X161.195 Y145.904 E0.09205
G1 X161.099 Y146.019 E0.09441
G1 X160.992 Y146.123 E0.09677
G1 X160.875 Y146.216 E0.09913
G1 X160.749 Y146.297 E0.10149
G1 X160.616 Y146.365 E0.10385
G1 X160.477 Y146.420 E0.10621
G1 X160.333 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11093
G1 X160.062 Y146.496 E0.11290
G1 X159.715 Y146.470 E0.11840
G1 X159.594 Y146.442 E0.12036
G1 X159.452 Y146.394 E0.12272
G1 X159.316 Y146.333 E0.12508
G1 X159.187 Y146.258 E0.12744
G1 X159.066 Y146.171 E0.12980
G1 X158.954 Y146.072 E0.13216
G1 X158.852 Y145.963 E0.13452
G1 X158.762 Y145.844 E0.13688
G1 X158.684 Y145.716 E0.13925
G1 X158.619 Y145.581 E0.14160
G1 X158.568 Y145.441 E0.14396
G1 X158.531 Y145.296 E0.14633
G1 X158.509 Y145.148 E0.14869
G1 X158.110 Y145.188 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00299 F10584
G1 X158.110 Y144.810 E0.00598
G1 X158.138 Y144.623 E0.00897
G1 X158.185 Y144.439 E0.01197
G1 X158.244 Y144.276 E0.01471
G1 X158.384 Y144.002 E0.01957
G1 X158.486 Y143.853 E0.02243
G1 X158.608 Y143.707 E0.02542
G1 X158.743 Y143.575 E0.02841
G1 X158.891 Y143.457 E0.03140
G1 X159.050 Y143.355 E0.03439
G1 X159.219 Y143.268 E0.03739
G1 X159.395 Y143.199 E0.04038
G1 X159.577 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04636
G1 X159.945 Y143.101 E0.04923
G1 X160.244 Y143.116 E0.05395
G1 X160.423 Y143.148 E0.05683
G1 X160.605 Y143.199 E0.05982
G1 X160.781 Y143.268 E0.06281
G1 X160.950 Y143.354 E0.06580
G1 X161.109 Y143.457 E0.06879
G1 X161.257 Y143.575 E0.07178
G1 X161.392 Y143.707 E0.07477
G1 X161.514 Y143.852 E0.07776
G1 X161.621 Y144.009 E0.08076
G1 X161.711 Y144.175 E0.08375
G1 X161.785 Y144.350 E0.08674
G1 X161.841 Y144.531 E0.08973
G1 X161.878 Y144.716 E0.09272
G1 X161.897 Y144.905 E0.09571
G1 X161.897 Y145.094 E0.09870
G1 X161.878 Y145.282 E0.10170
G1 X161.841 Y145.468 E0.10469
G1 X161.785 Y145.649 E0.10768
G1 X161.711 Y145.823 E0.11067
G1 X161.621 Y145.990 E0.11366
G1 X161.514 Y146.146 E0.11665
G1 X161.392 Y146.291 E0.11964
G1 X161.257 Y146.423 E0.12263
G1 X161.109 Y146.541 E0.12563
G1 X160.950 Y146.644 E0.12862
G1 X160.781 Y146.730 E0.13161
G1 X160.605 Y146.800 E0.13460
G1 X160.423 Y146.851 E0.13759
G1 X160.236 Y146.884 E0.14058
G1 X160.062 Y146.897 E0.14334
G1 X159.656 Y146.866 E0.14978
G1 X159.486 Y146.828 E0.15253
G1 X159.306 Y146.767 E0.15553
G1 X159.134 Y146.689 E0.15852
G1 X158.970 Y146.595 E0.16151
G1 X158.816 Y146.484 E0.16450
G1 X158.674 Y146.359 E0.16749
G1 X158.545 Y146.220 E0.17048
G1 X158.431 Y146.069 E0.17347
G1 X158.332 Y145.907 E0.17647
G1 X158.250 Y145.737 E0.17946
G1 X158.185 Y145.559 E0.18245
G1 X158.138 Y145.376 E0.18544
G1 X158.110 Y145.188 E0.18843
; feature outer perimeter
G1 X157.712 Y145.228 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00362 F9554
G1 X157.712 Y144.770 E0.00724
G1 X157.746 Y144.544 E0.01087
G1 X157.802 Y144.321 E0.01449
G1 X157.877 Y144.116 E0.01794
G1 X158.039 Y143.798 E0.02358
G1 X158.167 Y143.611 E0.02716
G1 X158.314 Y143.435 E0.03078
G1 X158.478 Y143.275 E0.03441
G1 X158.658 Y143.132 E0.03803
G1 X158.850 Y143.008 E0.04165
G1 X159.054 Y142.903 E0.04527
G1 X159.268 Y142.819 E0.04889
G1 X159.488 Y142.757 E0.05252
G1 X159.714 Y142.717 E0.05614
G1 X159.940 Y142.700 E0.05972
G1 X160.288 Y142.718 E0.06523
G1 X160.512 Y142.757 E0.06881
G1 X160.733 Y142.819 E0.07244
G1 X160.946 Y142.903 E0.07606
G1 X161.150 Y143.008 E0.07968
G1 X161.342 Y143.132 E0.08330
G1 X161.522 Y143.275 E0.08692
G1 X161.686 Y143.435 E0.09054
G1 X161.833 Y143.611 E0.09417
G1 X161.962 Y143.800 E0.09779
G1 X162.072 Y144.001 E0.10141
G1 X162.161 Y144.213 E0.10503
G1 X162.229 Y144.432 E0.10866
G1 X162.274 Y144.656 E0.11228
G1 X162.297 Y144.885 E0.11590
G1 X162.297 Y145.114 E0.11952
G1 X162.274 Y145.342 E0.12314
G1 X162.229 Y145.567 E0.12676
G1 X162.161 Y145.786 E0.13039
G1 X162.072 Y145.997 E0.13401
G1 X161.962 Y146.198 E0.13763
G1 X161.833 Y146.388 E0.14125
G1 X161.686 Y146.563 E0.14488
G1 X161.522 Y146.723 E0.14850
G1 X161.342 Y146.867 E0.15212
G1 X161.150 Y146.991 E0.15574
G1 X160.946 Y147.095 E0.15936
G1 X160.733 Y147.179 E0.16298
G1 X160.512 Y147.241 E0.16661
G1 X160.286 Y147.281 E0.17023
G1 X160.062 Y147.298 E0.17377
G1 X159.596 Y147.263 E0.18116
G1 X159.377 Y147.213 E0.18471
G1 X159.160 Y147.140 E0.18833
G1 X158.951 Y147.046 E0.19195
G1 X158.752 Y146.931 E0.19557
G1 X158.566 Y146.797 E0.19920
G1 X158.394 Y146.646 E0.20282
G1 X158.238 Y146.477 E0.20644
G1 X158.100 Y146.295 E0.21006
G1 X157.980 Y146.099 E0.21369
G1 X157.881 Y145.893 E0.21731
G1 X157.802 Y145.677 E0.22093
G1 X157.746 Y145.455 E0.22455
G1 X157.712 Y145.228 E0.22817
; feature solid layer
G1 X159.554 Y145.685 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00531 F15120
G1 X159.282 Y145.390 E0.00636
G1 X159.246 Y145.317 E0.00764
G1 X159.218 Y145.240 E0.00893
G1 X159.198 Y145.161 E0.01022
G1 X159.186 Y145.081 E0.01151
G1 X159.182 Y144.999 E0.01280
G1 X159.186 Y144.918 E0.01409
G1 X159.198 Y144.837 E0.01537
G1 X159.213 Y144.778 E0.01633
G1 X160.221 Y145.786 E0.03884
G1 X160.261 Y145.775 E0.03950
G1 X160.336 Y145.745 E0.04078
G1 X160.409 Y145.708 E0.04207
G1 X160.477 Y145.663 E0.04336
G1 X160.541 Y145.612 E0.04465
G1 X160.578 Y145.577 E0.04545
G1 X159.422 Y144.422 E0.07127
G1 X159.459 Y144.386 E0.07207
G1 X159.523 Y144.335 E0.07336
G1 X159.591 Y144.291 E0.07465
G1 X159.664 Y144.254 E0.07594
G1 X159.739 Y144.224 E0.07722
G1 X159.779 Y144.213 E0.07787
G1 X160.787 Y145.220 E0.10039
G1 X160.793 Y145.201 E0.10071
G1 X160.809 Y145.121 E0.10199
G1 X160.817 Y145.040 E0.10328
G1 X160.817 Y144.958 E0.10457
G1 X160.809 Y144.877 E0.10586
G1 X160.793 Y144.797 E0.10714
G1 X160.769 Y144.719 E0.10843
G1 X160.737 Y144.644 E0.10972
G1 X160.698 Y144.573 E0.11101
G1 X160.683 Y144.551 E0.11142
G1 X160.449 Y144.316 E0.11667
G92 E0.00000
G1 E-0.50000 F2400
; layer 46, Z = 4.8000
; feature inner perimeter
G1 Z4.8000 F2400
G1 X160.596 Y144.077 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.685 Y144.141 E0.00174 F10584
G1 X160.750 Y144.198 E0.00311
G1 X160.886 Y144.351 E0.00634
G1 X160.937 Y144.427 E0.00778
G1 X160.990 Y144.523 E0.00951
G1 X161.032 Y144.623 E0.01124
G1 X161.064 Y144.728 E0.01297
G1 X161.086 Y144.836 E0.01470
G1 X161.097 Y144.944 E0.01643
G1 X161.097 Y145.054 E0.01816
G1 X161.086 Y145.163 E0.01989
G1 X161.064 Y145.270 E0.02162
G1 X161.032 Y145.375 E0.02335
G1 X160.990 Y145.476 E0.02508
G1 X160.937 Y145.572 E0.02681
G1 X160.875 Y145.662 E0.02854
G1 X160.805 Y145.746 E0.03027
G1 X160.727 Y145.823 E0.03199
G1 X160.641 Y145.891 E0.03372
G1 X160.549 Y145.950 E0.03545
G1 X160.452 Y146.000 E0.03719
G1 X160.350 Y146.040 E0.03891
G1 X160.244 Y146.070 E0.04064
G1 X160.136 Y146.089 E0.04237
G1 X160.062 Y146.095 E0.04355
G1 X159.775 Y146.073 E0.04810
G1 X159.703 Y146.056 E0.04927
G1 X159.599 Y146.022 E0.05101
G1 X159.499 Y145.977 E0.05273
G1 X159.404 Y145.922 E0.05447
G1 X159.315 Y145.858 E0.05619
G1 X159.233 Y145.785 E0.05792
G1 X159.159 Y145.705 E0.05965
G1 X159.093 Y145.618 E0.06138
G1 X159.035 Y145.524 E0.06312
G1 X158.988 Y145.426 E0.06484
G1 X158.951 Y145.323 E0.06657
G1 X158.923 Y145.217 E0.06830
G1 X158.907 Y145.109 E0.07003
G1 X158.902 Y144.999 E0.07176
G1 X158.907 Y144.890 E0.07349
G1 X158.924 Y144.782 E0.07522
G1 X158.951 Y144.675 E0.07695
G1 X158.988 Y144.573 E0.07868
G1 X159.036 Y144.474 E0.08042
G1 X159.081 Y144.399 E0.08179
G1 X159.208 Y144.239 E0.08503
G1 X159.273 Y144.176 E0.08646
G1 X159.359 Y144.108 E0.08819
G1 X159.451 Y144.048 E0.08992
G1 X159.548 Y143.998 E0.09165
G1 X159.650 Y143.958 E0.09338
G1 X159.756 Y143.928 E0.09511
G1 X159.863 Y143.909 E0.09684
G1 X159.972 Y143.901 E0.09856
G1 X160.082 Y143.904 E0.10030
G1 X160.191 Y143.918 E0.10203
G1 X160.297 Y143.942 E0.10376
G1 X160.401 Y143.977 E0.10549
G1 X160.501 Y144.022 E0.10722
G1 X160.596 Y144.077 E0.10895
G1 X160.813 Y143.740 F18000
G92 E0.00000
G1 X160.935 Y143.828 E0.00237 F10584
G1 X161.033 Y143.915 E0.00445
G1 X161.202 Y144.105 E0.00847
G1 X161.279 Y144.218 E0.01062
G1 X161.350 Y144.349 E0.01298
G1 X161.408 Y144.487 E0.01534
G1 X161.452 Y144.629 E0.01770
G1 X161.482 Y144.776 E0.02006
G1 X161.497 Y144.924 E0.02242
G1 X161.497 Y145.074 E0.02478
G1 X161.482 Y145.223 E0.02714
G1 X161.452 Y145.369 E0.02950
G1 X161.408 Y145.512 E0.03186
G1 X161.350 Y145.649 E0.03422
G1 X161.279 Y145.781 E0.03658
G1 X161.195 Y145.904 E0.03894
G1 X161.099 Y146.019 E0.04131
G1 X160.992 Y146.123 E0.04366
G1 X160.875 Y146.216 E0.04602
G1 X160.749 Y146.297 E0.04839
G1 X160.616 Y146.365 E0.05075
G1 X160.477 Y146.420 E0.05311
G1 X160.333 Y146.460 E0.05547
G1 X160.186 Y146.486 E0.05783
G1 X160.062 Y146.496 E0.05979
G1 X159.715 Y146.470 E0.06529
G1 X159.594 Y146.442 E0.06725
G1 X159.452 Y146.394 E0.06962
G1 X159.316 Y146.333 E0.07198
G1 X159.187 Y146.258 E0.07434
G1 X159.066 Y146.171 E0.07670
G1 X158.954 Y146.072 E0.07906
G1 X158.852 Y145.963 E0.08142
G1 X158.762 Y145.844 E0.08378
G1 X158.684 Y145.716 E0.08614
G1 X158.619 Y145.581 E0.08850
G1 X158.568 Y145.441 E0.09086
G1 X158.531 Y145.296 E0.09322
G1 X158.509 Y145.148 E0.09558
G1 X158.501 Y144.999 E0.09794
G1 X158.509 Y144.850 E0.10030
G1 X158.531 Y144.702 E0.10266
G1 X158.568 Y144.557 E0.10502
G1 X158.619 Y144.417 E0.10739
G1 X158.684 Y144.282 E0.10975
G1 X158.752 Y144.170 E0.11183
G1 X158.911 Y143.970 E0.11585
G1 X159.008 Y143.876 E0.11800
G1 X159.125 Y143.782 E0.12036
G1 X159.251 Y143.701 E0.12272
G1 X159.384 Y143.633 E0.12509
G1 X159.523 Y143.579 E0.12744
G1 X159.667 Y143.538 E0.12981
G1 X159.814 Y143.512 E0.13217
G1 X159.962 Y143.501 E0.13452
G1 X160.112 Y143.505 E0.13689
G1 X160.260 Y143.523 E0.13925
G1 X160.406 Y143.557 E0.14161
G1 X160.548 Y143.604 E0.14397
G1 X160.684 Y143.666 E0.14633
G1 X160.813 Y143.740 E0.14869
G1 X161.030 Y143.404 F18000
G92 E0.00000
G1 X161.184 Y143.515 E0.00300 F10584
G1 X161.316 Y143.631 E0.00578
G1 X161.518 Y143.859 E0.01059
G1 X161.621 Y144.009 E0.01346
G1 X161.711 Y144.175 E0.01645
G1 X161.785 Y144.350 E0.01944
G1 X161.841 Y144.531 E0.02243
G1 X161.878 Y144.716 E0.02542
G1 X161.897 Y144.905 E0.02841
G1 X161.897 Y145.094 E0.03141
G1 X161.878 Y145.282 E0.03440
G1 X161.841 Y145.468 E0.03739
G1 X161.785 Y145.649 E0.04038
G1 X161.711 Y145.823 E0.04337
G1 X161.621 Y145.990 E0.04636
G1 X161.514 Y146.146 E0.04935
G1 X161.392 Y146.291 E0.05234
G1 X161.257 Y146.423 E0.05533
G1 X161.109 Y146.541 E0.05833
G1 X160.950 Y146.644 E0.06132
G1 X160.781 Y146.730 E0.06431
G1 X160.605 Y146.800 E0.06730
G1 X160.423 Y146.851 E0.07029
G1 X160.236 Y146.884 E0.07328
G1 X160.062 Y146.897 E0.07604
G1 X159.656 Y146.866 E0.08248
G1 X159.486 Y146.828 E0.08523
G1 X159.306 Y146.767 E0.08823
G1 X159.134 Y146.689 E0.09122
G1 X158.970 Y146.595 E0.09421
G1 X158.816 Y146.484 E0.09720
G1 X158.674 Y146.359 E0.10019
G1 X158.545 Y146.220 E0.10318
G1 X158.431 Y146.069 E0.10617
G1 X158.332 Y145.907 E0.10917
G1 X158.250 Y145.737 E0.11216
G1 X158.185 Y145.559 E0.11515
G1 X158.138 Y145.376 E0.11814
G1 X158.110 Y145.188 E0.12113
G1 X158.101 Y144.999 E0.12412
G1 X158.110 Y144.810 E0.12711
G1 X158.138 Y144.623 E0.13010
G1 X158.185 Y144.439 E0.13310
G1 X158.250 Y144.261 E0.13609
G1 X158.332 Y144.091 E0.13908
G1 X158.424 Y143.940 E0.14186
G1 X158.613 Y143.702 E0.14668
G1 X158.743 Y143.575 E0.14954
G1 X158.891 Y143.457 E0.15254
G1 X159.050 Y143.355 E0.15552
G1 X159.219 Y143.268 E0.15852
G1 X159.395 Y143.199 E0.16151
G1 X159.577 Y143.148 E0.16450
G1 X159.764 Y143.115 E0.16749
G1 X159.953 Y143.101 E0.17048
G1 X160.142 Y143.105 E0.17347
G1 X160.330 Y143.129 E0.17647
G1 X160.514 Y143.171 E0.17946
G1 X160.694 Y143.231 E0.18245
G1 X160.866 Y143.309 E0.18544
G1 X161.030 Y143.404 E0.18843
; feature outer perimeter
G1 X161.248 Y143.067 F18000
G92 E0.00000
G1 X161.434 Y143.201 E0.00362 F9554
G1 X161.600 Y143.347 E0.00711
G1 X161.835 Y143.613 E0.01272
G1 X161.962 Y143.800 E0.01630
G1 X162.072 Y144.001 E0.01992
G1 X162.161 Y144.213 E0.02354
G1 X162.229 Y144.432 E0.02716
G1 X162.274 Y144.656 E0.03078
G1 X162.297 Y144.885 E0.03441
G1 X162.297 Y145.114 E0.03803
G1 X162.274 Y145.342 E0.04165
G1 X162.229 Y145.567 E0.04527
G1 X162.161 Y145.786 E0.04889
G1 X162.072 Y145.997 E0.05252
G1 X161.962 Y146.198 E0.05614
G1 X161.833 Y146.388 E0.05976
G1 X161.686 Y146.563 E0.06338
G1 X161.522 Y146.723 E0.06700
G1 X161.342 Y146.867 E0.07063
G1 X161.150 Y146.991 E0.07425
G1 X160.946 Y147.095 E0.07787
G1 X160.733 Y147.179 E0.08149
G1 X160.512 Y147.241 E0.08512
G1 X160.286 Y147.281 E0.08874
G1 X160.062 Y147.298 E0.09228
G1 X159.596 Y147.263 E0.09967
G1 X159.377 Y147.213 E0.10322
G1 X159.160 Y147.140 E0.10684
G1 X158.951 Y147.046 E0.11046
G1 X158.752 Y146.931 E0.11408
G1 X158.566 Y146.797 E0.11770
G1 X158.394 Y146.646 E0.12133
G1 X158.238 Y146.477 E0.12495
G1 X158.100 Y146.295 E0.12857
G1 X157.980 Y146.099 E0.13219
G1 X157.881 Y145.893 E0.13581
G1 X157.802 Y145.677 E0.13943
G1 X157.746 Y145.455 E0.14306
G1 X157.712 Y145.228 E0.14668
G1 X157.700 Y144.999 E0.15030
G1 X157.712 Y144.770 E0.15392
G1 X157.746 Y144.544 E0.15755
G1 X157.802 Y144.321 E0.16117
G1 X157.881 Y144.106 E0.16479
G1 X157.980 Y143.899 E0.16841
G1 X158.095 Y143.711 E0.17190
G1 X158.316 Y143.433 E0.17751
G1 X158.478 Y143.275 E0.18109
G1 X158.658 Y143.132 E0.18471
G1 X158.850 Y143.008 E0.18833
G1 X159.054 Y142.903 E0.19195
G1 X159.268 Y142.819 E0.19557
G1 X159.488 Y142.757 E0.19920
G1 X159.714 Y142.717 E0.20282
G1 X159.943 Y142.700 E0.20644
G1 X160.172 Y142.706 E0.21006
G1 X160.399 Y142.734 E0.21368
G1 X160.623 Y142.785 E0.21731
G1 X160.840 Y142.858 E0.22093
G1 X161.049 Y142.953 E0.22455
G1 X161.248 Y143.067 E0.22817
; feature solid layer
G1 X159.322 Y144.546 F18000
G92 E0.00000
G1 X159.552 Y144.316 E0.00512 F15120
G1 X159.591 Y144.291 E0.00586
G1 X159.664 Y144.254 E0.00715
G1 X159.739 Y144.224 E0.00844
G1 X159.818 Y144.202 E0.00973
G1 X159.898 Y144.188 E0.01102
G1 X159.979 Y144.182 E0.01230
G1 X160.061 Y144.184 E0.01359
G1 X160.142 Y144.194 E0.01488
G1 X160.222 Y144.212 E0.01617
G1 X159.213 Y145.220 E0.03870
G1 X159.218 Y145.240 E0.03903
G1 X159.246 Y145.317 E0.04032
G1 X159.282 Y145.390 E0.04160
G1 X159.324 Y145.460 E0.04289
G1 X159.373 Y145.525 E0.04418
G1 X159.422 Y145.577 E0.04531
G1 X160.576 Y144.424 E0.07109
G1 X160.665 Y144.524 E0.07320
G1 X160.698 Y144.573 E0.07414
G1 X160.737 Y144.644 E0.07543
G1 X160.769 Y144.719 E0.07671
G1 X160.787 Y144.778 E0.07769
G1 X159.778 Y145.787 E0.10021
G1 X159.817 Y145.795 E0.10084
G1 X160.062 Y145.814 E0.10472
G1 X160.102 Y145.811 E0.10535
G1 X160.182 Y145.797 E0.10663
G1 X160.261 Y145.775 E0.10792
G1 X160.336 Y145.745 E0.10921
G1 X160.409 Y145.708 E0.11050
G1 X160.449 Y145.682 E0.11126
G1 X160.683 Y145.448 E0.11647
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F15120
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F15120
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F15120
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer 47, Z = 4.9000
; feature inner perimeter
G1 Z4.9000 F2400
G1 X138.900 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y153.900 E0.19274 F15120
G1 X151.100 Y156.100 E0.22750
G1 X138.900 Y156.100 E0.42024
G1 X138.900 Y153.900 E0.45500
G1 X138.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y153.500 E0.20538 F15120
G1 X151.500 Y156.500 E0.25278
G1 X138.500 Y156.500 E0.45816
G1 X138.500 Y153.500 E0.50555
G1 X138.100 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y153.100 E0.21802 F15120
G1 X151.900 Y156.900 E0.27805
G1 X138.100 Y156.900 E0.49607
G1 X138.100 Y153.100 E0.55611
; feature outer perimeter
G1 X137.700 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y152.700 E0.23066 F13230
G1 X152.300 Y157.300 E0.30333
G1 X137.700 Y157.300 E0.53399
G1 X137.700 Y152.700 E0.60666
; feature solid layer
G1 X139.597 Y155.820 F18000
G92 E0.00000
G1 X139.180 Y155.403 E0.00933 F15120
G1 X139.180 Y154.837 E0.01826
G1 X140.163 Y155.820 E0.04023
G1 X140.729 Y155.820 E0.04916
G1 X139.180 Y154.271 E0.08377
G1 X139.180 Y154.180 E0.08521
G1 X139.654 Y154.180 E0.09270
G1 X141.294 Y155.820 E0.12935
G1 X141.860 Y155.820 E0.13828
G1 X140.220 Y154.180 E0.17493
G1 X140.786 Y154.180 E0.18386
G1 X142.426 Y155.820 E0.22050
G1 X142.992 Y155.820 E0.22944
G1 X141.352 Y154.180 E0.26608
G1 X141.917 Y154.180 E0.27502
G1 X143.557 Y155.820 E0.31166
G1 X144.123 Y155.820 E0.32060
G1 X142.483 Y154.180 E0.35724
G1 X143.049 Y154.180 E0.36618
G1 X144.689 Y155.820 E0.40282
G1 X145.254 Y155.820 E0.41176
G1 X143.614 Y154.180 E0.44840
G1 X144.180 Y154.180 E0.45734
G1 X145.820 Y155.820 E0.49398
G1 X146.386 Y155.820 E0.50291
G1 X144.746 Y154.180 E0.53956
G1 X145.311 Y154.180 E0.54849
G1 X146.951 Y155.820 E0.58514
G1 X147.517 Y155.820 E0.59407
G1 X145.877 Y154.180 E0.63071
G1 X146.443 Y154.180 E0.63965
G1 X148.083 Y155.820 E0.67629
G1 X148.648 Y155.820 E0.68523
G1 X147.008 Y154.180 E0.72187
G1 X147.574 Y154.180 E0.73081
G1 X149.214 Y155.820 E0.76745
G1 X149.780 Y155.820 E0.77639
G1 X148.140 Y154.180 E0.81303
G1 X148.705 Y154.180 E0.82197
G1 X150.345 Y155.820 E0.85861
G1 X150.820 Y155.820 E0.86611
G1 X150.820 Y155.729 E0.86755
G1 X149.271 Y154.180 E0.90215
G1 X149.837 Y154.180 E0.91109
G1 X150.820 Y155.163 E0.93306
G1 X150.820 Y154.598 E0.94199
G1 X150.402 Y154.180 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
; feature solid layer
G1 X139.689 Y145.820 F18000
G92 E0.00000
G1 X139.180 Y145.311 E0.01136 F15120
G1 X139.180 Y144.746 E0.02030
G1 X140.254 Y145.820 E0.04430
G1 X140.820 Y145.820 E0.05324
G1 X139.180 Y144.180 E0.08988
G1 X139.746 Y144.180 E0.09882
G1 X140.820 Y145.254 E0.12282
G1 X140.820 Y144.689 E0.13176
G1 X140.311 Y144.180 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
; feature solid layer
G1 X150.311 Y144.180 F18000
G92 E0.00000
G1 X150.820 Y144.689 E0.01137 F15120
G1 X150.820 Y145.254 E0.02030
G1 X149.746 Y144.180 E0.04431
G1 X149.180 Y144.180 E0.05324
G1 X150.820 Y145.820 E0.08989
G1 X150.254 Y145.820 E0.09882
G1 X149.180 Y144.746 E0.12282
G1 X149.180 Y145.311 E0.13176
G1 X149.689 Y145.820 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 4
; feature inner perimeter
G1 X158.907 Y145.110 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X158.902 Y144.999 E0.00176 F10584
G1 X158.908 Y144.887 E0.00353
G1 X158.923 Y144.782 E0.00521
G1 X158.950 Y144.678 E0.00691
G1 X158.987 Y144.574 E0.00865
G1 X159.036 Y144.473 E0.01042
G1 X159.091 Y144.383 E0.01209
G1 X159.159 Y144.292 E0.01388
G1 X159.220 Y144.228 E0.01528
G1 X159.372 Y144.099 E0.01843
G1 X159.452 Y144.048 E0.01993
G1 X159.546 Y143.999 E0.02160
G1 X159.649 Y143.959 E0.02335
G1 X159.754 Y143.929 E0.02507
G1 X159.864 Y143.909 E0.02685
G1 X159.970 Y143.901 E0.02852
G1 X160.080 Y143.904 E0.03027
G1 X160.189 Y143.917 E0.03199
G1 X160.296 Y143.942 E0.03372
G1 X160.400 Y143.976 E0.03546
G1 X160.500 Y144.021 E0.03718
G1 X160.594 Y144.076 E0.03891
G1 X160.683 Y144.140 E0.04064
G1 X160.766 Y144.212 E0.04237
G1 X160.840 Y144.292 E0.04410
G1 X160.906 Y144.379 E0.04583
G1 X160.964 Y144.473 E0.04756
G1 X161.011 Y144.571 E0.04929
G1 X161.050 Y144.676 E0.05106
G1 X161.071 Y144.761 E0.05244
G1 X161.097 Y144.966 E0.05570
G1 X161.097 Y145.051 E0.05705
G1 X161.086 Y145.164 E0.05883
G1 X161.064 Y145.271 E0.06056
G1 X161.033 Y145.373 E0.06224
G1 X160.990 Y145.474 E0.06399
G1 X160.938 Y145.571 E0.06572
G1 X160.876 Y145.661 E0.06744
G1 X160.806 Y145.745 E0.06918
G1 X160.728 Y145.821 E0.07090
G1 X160.640 Y145.891 E0.07268
G1 X160.551 Y145.949 E0.07435
G1 X160.453 Y146.000 E0.07609
G1 X160.351 Y146.040 E0.07782
G1 X160.246 Y146.069 E0.07955
G1 X160.136 Y146.089 E0.08132
G1 X160.047 Y146.096 E0.08273
G1 X159.848 Y146.086 E0.08588
G1 X159.775 Y146.073 E0.08705
G1 X159.582 Y146.014 E0.09024
G1 X159.501 Y145.978 E0.09164
G1 X159.406 Y145.923 E0.09338
G1 X159.317 Y145.859 E0.09510
G1 X159.232 Y145.785 E0.09688
G1 X159.160 Y145.707 E0.09855
G1 X159.092 Y145.617 E0.10033
G1 X159.035 Y145.524 E0.10206
G1 X158.988 Y145.426 E0.10378
G1 X158.951 Y145.325 E0.10547
G1 X158.924 Y145.219 E0.10721
G1 X158.907 Y145.110 E0.10894
G1 X158.509 Y145.151 F18000
G92 E0.00000
G1 X158.501 Y144.999 E0.00240 F10584
G1 X158.509 Y144.847 E0.00480
G1 X158.531 Y144.702 E0.00712
G1 X158.567 Y144.560 E0.00943
G1 X158.618 Y144.419 E0.01180
G1 X158.684 Y144.282 E0.01421
G1 X158.760 Y144.157 E0.01651
G1 X158.852 Y144.035 E0.01893
G1 X158.943 Y143.938 E0.02104
G1 X159.134 Y143.777 E0.02498
G1 X159.251 Y143.701 E0.02719
G1 X159.381 Y143.634 E0.02949
G1 X159.521 Y143.579 E0.03186
G1 X159.664 Y143.539 E0.03422
G1 X159.814 Y143.512 E0.03663
G1 X159.960 Y143.501 E0.03894
G1 X160.110 Y143.505 E0.04130
G1 X160.258 Y143.523 E0.04366
G1 X160.404 Y143.556 E0.04602
G1 X160.546 Y143.603 E0.04839
G1 X160.682 Y143.665 E0.05074
G1 X160.811 Y143.739 E0.05311
G1 X160.933 Y143.826 E0.05547
G1 X161.045 Y143.925 E0.05783
G1 X161.147 Y144.034 E0.06018
G1 X161.237 Y144.153 E0.06255
G1 X161.315 Y144.281 E0.06491
G1 X161.380 Y144.415 E0.06727
G1 X161.432 Y144.558 E0.06967
G1 X161.465 Y144.687 E0.07177
G1 X161.497 Y144.941 E0.07582
G1 X161.497 Y145.071 E0.07787
G1 X161.482 Y145.223 E0.08029
G1 X161.452 Y145.369 E0.08265
G1 X161.409 Y145.509 E0.08496
G1 X161.351 Y145.647 E0.08733
G1 X161.280 Y145.779 E0.08969
G1 X161.196 Y145.902 E0.09204
G1 X161.100 Y146.017 E0.09441
G1 X160.993 Y146.121 E0.09677
G1 X160.874 Y146.217 E0.09917
G1 X160.752 Y146.296 E0.10148
G1 X160.618 Y146.364 E0.10385
G1 X160.479 Y146.419 E0.10621
G1 X160.336 Y146.460 E0.10857
G1 X160.186 Y146.486 E0.11098
G1 X160.053 Y146.496 E0.11309
G1 X159.804 Y146.484 E0.11702
G1 X159.681 Y146.463 E0.11899
G1 X159.440 Y146.389 E0.12297
G1 X159.319 Y146.334 E0.12508
G1 X159.189 Y146.259 E0.12744
G1 X159.068 Y146.172 E0.12980
G1 X158.953 Y146.072 E0.13221
G1 X158.854 Y145.965 E0.13452
G1 X158.761 Y145.843 E0.13693
G1 X158.684 Y145.716 E0.13928
G1 X158.619 Y145.581 E0.14164
G1 X158.569 Y145.444 E0.14396
G1 X158.532 Y145.298 E0.14633
G1 X158.509 Y145.151 E0.14869
G1 X158.111 Y145.191 F18000
G92 E0.00000
G1 X158.101 Y144.999 E0.00304 F10584
G1 X158.111 Y144.807 E0.00608
G1 X158.138 Y144.623 E0.00902
G1 X158.184 Y144.443 E0.01196
G1 X158.249 Y144.264 E0.01496
G1 X158.332 Y144.090 E0.01800
G1 X158.429 Y143.932 E0.02093
G1 X158.545 Y143.778 E0.02398
G1 X158.667 Y143.647 E0.02680
G1 X158.895 Y143.455 E0.03152
G1 X159.051 Y143.354 E0.03445
G1 X159.216 Y143.269 E0.03738
G1 X159.392 Y143.200 E0.04038
G1 X159.575 Y143.148 E0.04337
G1 X159.764 Y143.115 E0.04641
G1 X159.950 Y143.101 E0.04935
G1 X160.139 Y143.105 E0.05234
G1 X160.327 Y143.128 E0.05533
G1 X160.512 Y143.170 E0.05832
G1 X160.691 Y143.230 E0.06132
G1 X160.864 Y143.308 E0.06431
G1 X161.028 Y143.402 E0.06730
G1 X161.182 Y143.513 E0.07029
G1 X161.324 Y143.638 E0.07328
G1 X161.453 Y143.776 E0.07627
G1 X161.568 Y143.927 E0.07926
G1 X161.667 Y144.089 E0.08226
G1 X161.749 Y144.259 E0.08524
G1 X161.815 Y144.440 E0.08829
G1 X161.859 Y144.612 E0.09110
G1 X161.897 Y144.916 E0.09593
G1 X161.897 Y145.091 E0.09869
G1 X161.878 Y145.283 E0.10174
G1 X161.840 Y145.468 E0.10473
G1 X161.786 Y145.646 E0.10767
G1 X161.712 Y145.821 E0.11066
G1 X161.622 Y145.987 E0.11366
G1 X161.516 Y146.144 E0.11665
G1 X161.394 Y146.289 E0.11964
G1 X161.259 Y146.421 E0.12263
G1 X161.108 Y146.542 E0.12567
G1 X160.952 Y146.642 E0.12861
G1 X160.784 Y146.729 E0.13161
G1 X160.608 Y146.799 E0.13459
G1 X160.425 Y146.850 E0.13759
G1 X160.236 Y146.884 E0.14063
G1 X160.058 Y146.897 E0.14345
G1 X159.759 Y146.883 E0.14817
G1 X159.588 Y146.853 E0.15092
G1 X159.299 Y146.764 E0.15569
G1 X159.136 Y146.691 E0.15851
G1 X158.972 Y146.596 E0.16151
G1 X158.818 Y146.486 E0.16450
G1 X158.674 Y146.359 E0.16754
G1 X158.547 Y146.222 E0.17048
G1 X158.431 Y146.069 E0.17352
G1 X158.332 Y145.907 E0.17651
G1 X158.250 Y145.737 E0.17950
G1 X158.186 Y145.562 E0.18244
G1 X158.139 Y145.378 E0.18544
G1 X158.111 Y145.191 E0.18843
; feature outer perimeter
G1 X157.712 Y145.232 F18000
G92 E0.00000
G1 X157.700 Y144.999 E0.00368 F9554
G1 X157.712 Y144.767 E0.00736
G1 X157.746 Y144.544 E0.01092
G1 X157.801 Y144.325 E0.01449
G1 X157.880 Y144.109 E0.01811
G1 X157.980 Y143.899 E0.02179
G1 X158.098 Y143.707 E0.02535
G1 X158.238 Y143.521 E0.02903
G1 X158.390 Y143.357 E0.03256
G1 X158.657 Y143.133 E0.03807
G1 X158.850 Y143.008 E0.04171
G1 X159.051 Y142.905 E0.04527
G1 X159.264 Y142.820 E0.04889
G1 X159.485 Y142.758 E0.05252
G1 X159.714 Y142.717 E0.05619
G1 X159.939 Y142.700 E0.05976
G1 X160.168 Y142.706 E0.06338
G1 X160.396 Y142.734 E0.06700
G1 X160.620 Y142.785 E0.07063
G1 X160.837 Y142.857 E0.07425
G1 X161.046 Y142.951 E0.07787
G1 X161.245 Y143.066 E0.08149
G1 X161.431 Y143.199 E0.08511
G1 X161.603 Y143.351 E0.08873
G1 X161.759 Y143.518 E0.09236
G1 X161.898 Y143.701 E0.09598
G1 X162.018 Y143.896 E0.09960
G1 X162.118 Y144.103 E0.10322
G1 X162.198 Y144.321 E0.10690
G1 X162.253 Y144.538 E0.11042
G1 X162.297 Y144.891 E0.11605
G1 X162.297 Y145.110 E0.11952
G1 X162.274 Y145.342 E0.12320
G1 X162.229 Y145.567 E0.12682
G1 X162.162 Y145.782 E0.13038
G1 X162.073 Y145.994 E0.13401
G1 X161.964 Y146.195 E0.13763
G1 X161.835 Y146.385 E0.14125
G1 X161.688 Y146.561 E0.14487
G1 X161.524 Y146.721 E0.14849
G1 X161.342 Y146.867 E0.15217
G1 X161.153 Y146.989 E0.15574
G1 X160.949 Y147.094 E0.15936
G1 X160.736 Y147.178 E0.16298
G1 X160.515 Y147.240 E0.16660
G1 X160.286 Y147.281 E0.17028
G1 X160.063 Y147.298 E0.17380
G1 X159.715 Y147.281 E0.17932
G1 X159.494 Y147.242 E0.18286
G1 X159.157 Y147.139 E0.18842
G1 X158.954 Y147.047 E0.19195
G1 X158.755 Y146.933 E0.19557
G1 X158.569 Y146.799 E0.19919
G1 X158.394 Y146.645 E0.20287
G1 X158.241 Y146.480 E0.20644
G1 X158.100 Y146.295 E0.21012
G1 X157.980 Y146.099 E0.21374
G1 X157.881 Y145.893 E0.21736
G1 X157.804 Y145.680 E0.22093
G1 X157.747 Y145.458 E0.22455
G1 X157.712 Y145.232 E0.22817
; feature solid layer
G1 X159.553 Y145.684 F18000
G92 E0.00000
G1 X159.316 Y145.447 E0.00530 F15120
G1 X159.282 Y145.390 E0.00635
G1 X159.246 Y145.317 E0.00764
G1 X159.219 Y145.242 E0.00889
G1 X159.199 Y145.163 E0.01019
G1 X159.186 Y145.082 E0.01148
G1 X159.182 Y144.999 E0.01279
G1 X159.186 Y144.915 E0.01411
G1 X159.198 Y144.837 E0.01536
G1 X159.213 Y144.778 E0.01632
G1 X160.221 Y145.786 E0.03883
G1 X160.262 Y145.774 E0.03951
G1 X160.337 Y145.744 E0.04079
G1 X160.411 Y145.706 E0.04209
G1 X160.476 Y145.664 E0.04333
G1 X160.542 Y145.611 E0.04466
G1 X160.578 Y145.577 E0.04544
G1 X159.423 Y144.422 E0.07124
G1 X159.539 Y144.325 E0.07363
G1 X159.592 Y144.290 E0.07463
G1 X159.662 Y144.255 E0.07587
G1 X159.738 Y144.224 E0.07717
G1 X159.779 Y144.213 E0.07784
G1 X160.787 Y145.220 E0.10035
G1 X160.793 Y145.201 E0.10066
G1 X160.809 Y145.122 E0.10194
G1 X160.817 Y145.037 E0.10329
G1 X160.817 Y144.983 E0.10414
G1 X160.796 Y144.813 E0.10685
G1 X160.782 Y144.759 E0.10773
G1 X160.753 Y144.680 E0.10905
G1 X160.718 Y144.607 E0.11034
G1 X160.684 Y144.552 E0.11137
G1 X160.446 Y144.314 E0.11668
G92 E0.00000
G1 E-0.50000 F2400
; layer 48, Z = 5.0000
; feature inner perimeter
G1 Z5.0000 F2400
G1 X160.596 Y144.076 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X160.684 Y144.140 E0.00173 F10584
G1 X160.753 Y144.201 E0.00318
G1 X160.885 Y144.350 E0.00632
G1 X160.937 Y144.426 E0.00778
G1 X160.989 Y144.522 E0.00950
G1 X161.032 Y144.623 E0.01124
G1 X161.064 Y144.728 E0.01297
G1 X161.086 Y144.835 E0.01470
G1 X161.097 Y144.944 E0.01642
G1 X161.097 Y145.053 E0.01815
G1 X161.086 Y145.163 E0.01990
G1 X161.064 Y145.270 E0.02162
G1 X161.032 Y145.374 E0.02334
G1 X160.990 Y145.475 E0.02507
G1 X160.937 Y145.572 E0.02680
G1 X160.876 Y145.662 E0.02853
G1 X160.805 Y145.746 E0.03026
G1 X160.727 Y145.822 E0.03199
G1 X160.641 Y145.891 E0.03374
G1 X160.550 Y145.950 E0.03545
G1 X160.452 Y146.000 E0.03718
G1 X160.350 Y146.040 E0.03891
G1 X160.245 Y146.070 E0.04064
G1 X160.136 Y146.089 E0.04238
G1 X160.046 Y146.096 E0.04382
G1 X159.847 Y146.086 E0.04696
G1 X159.773 Y146.073 E0.04814
G1 X159.582 Y146.014 E0.05130
G1 X159.500 Y145.977 E0.05273
G1 X159.405 Y145.922 E0.05446
G1 X159.316 Y145.858 E0.05620
G1 X159.233 Y145.785 E0.05794
G1 X159.159 Y145.706 E0.05965
G1 X159.092 Y145.618 E0.06140
G1 X159.035 Y145.524 E0.06312
G1 X158.988 Y145.426 E0.06485
G1 X158.951 Y145.324 E0.06657
G1 X158.924 Y145.217 E0.06830
G1 X158.907 Y145.109 E0.07003
G1 X158.902 Y144.999 E0.07178
G1 X158.907 Y144.891 E0.07349
G1 X158.924 Y144.781 E0.07524
G1 X158.950 Y144.676 E0.07695
G1 X158.988 Y144.573 E0.07868
G1 X159.036 Y144.474 E0.08042
G1 X159.092 Y144.381 E0.08214
G1 X159.159 Y144.293 E0.08389
G1 X159.221 Y144.226 E0.08532
G1 X159.373 Y144.098 E0.08846
G1 X159.451 Y144.048 E0.08993
G1 X159.548 Y143.998 E0.09165
G1 X159.650 Y143.958 E0.09338
G1 X159.755 Y143.929 E0.09510
G1 X159.864 Y143.909 E0.09686
G1 X159.972 Y143.901 E0.09856
G1 X160.082 Y143.904 E0.10030
G1 X160.190 Y143.918 E0.10203
G1 X160.297 Y143.942 E0.10376
G1 X160.401 Y143.977 E0.10549
G1 X160.500 Y144.022 E0.10722
G1 X160.596 Y144.076 E0.10895
G1 X160.813 Y143.740 F18000
G92 E0.00000
G1 X160.934 Y143.827 E0.00236 F10584
G1 X161.037 Y143.918 E0.00452
G1 X161.201 Y144.104 E0.00845
G1 X161.278 Y144.217 E0.01061
G1 X161.350 Y144.348 E0.01297
G1 X161.408 Y144.486 E0.01534
G1 X161.452 Y144.629 E0.01770
G1 X161.482 Y144.775 E0.02006
G1 X161.497 Y144.924 E0.02242
G1 X161.497 Y145.073 E0.02478
G1 X161.482 Y145.223 E0.02716
G1 X161.452 Y145.369 E0.02951
G1 X161.409 Y145.511 E0.03186
G1 X161.351 Y145.649 E0.03422
G1 X161.279 Y145.780 E0.03658
G1 X161.195 Y145.904 E0.03894
G1 X161.099 Y146.018 E0.04130
G1 X160.992 Y146.122 E0.04366
G1 X160.875 Y146.216 E0.04604
G1 X160.750 Y146.297 E0.04838
G1 X160.617 Y146.365 E0.05075
G1 X160.478 Y146.420 E0.05310
G1 X160.334 Y146.460 E0.05546
G1 X160.186 Y146.486 E0.05784
G1 X160.051 Y146.497 E0.05998
G1 X159.802 Y146.484 E0.06392
G1 X159.680 Y146.463 E0.06588
G1 X159.441 Y146.389 E0.06983
G1 X159.317 Y146.333 E0.07197
G1 X159.188 Y146.259 E0.07434
G1 X159.066 Y146.171 E0.07670
G1 X158.953 Y146.072 E0.07907
G1 X158.852 Y145.963 E0.08142
G1 X158.762 Y145.843 E0.08379
G1 X158.684 Y145.716 E0.08615
G1 X158.619 Y145.581 E0.08851
G1 X158.568 Y145.442 E0.09086
G1 X158.531 Y145.297 E0.09322
G1 X158.509 Y145.149 E0.09558
G1 X158.501 Y144.999 E0.09796
G1 X158.509 Y144.851 E0.10030
G1 X158.531 Y144.702 E0.10268
G1 X158.568 Y144.558 E0.10502
G1 X158.619 Y144.418 E0.10738
G1 X158.684 Y144.282 E0.10976
G1 X158.761 Y144.156 E0.11210
G1 X158.852 Y144.036 E0.11448
G1 X158.944 Y143.936 E0.11663
G1 X159.135 Y143.776 E0.12056
G1 X159.251 Y143.701 E0.12274
G1 X159.383 Y143.633 E0.12508
G1 X159.522 Y143.579 E0.12744
G1 X159.666 Y143.538 E0.12980
G1 X159.814 Y143.512 E0.13218
G1 X159.962 Y143.501 E0.13452
G1 X160.111 Y143.505 E0.13689
G1 X160.260 Y143.523 E0.13925
G1 X160.405 Y143.556 E0.14161
G1 X160.547 Y143.604 E0.14397
G1 X160.683 Y143.665 E0.14633
G1 X160.813 Y143.740 E0.14869
G1 X161.030 Y143.403 F18000
G92 E0.00000
G1 X161.183 Y143.514 E0.00299 F10584
G1 X161.320 Y143.634 E0.00586
G1 X161.518 Y143.858 E0.01058
G1 X161.620 Y144.008 E0.01346
G1 X161.711 Y144.174 E0.01644
G1 X161.784 Y144.349 E0.01944
G1 X161.840 Y144.530 E0.02243
G1 X161.878 Y144.715 E0.02542
G1 X161.897 Y144.904 E0.02841
G1 X161.897 Y145.093 E0.03140
G1 X161.878 Y145.283 E0.03441
G1 X161.841 Y145.468 E0.03740
G1 X161.785 Y145.648 E0.04037
G1 X161.712 Y145.822 E0.04337
G1 X161.621 Y145.989 E0.04636
G1 X161.515 Y146.145 E0.04935
G1 X161.393 Y146.290 E0.05234
G1 X161.257 Y146.423 E0.05533
G1 X161.109 Y146.541 E0.05834
G1 X160.951 Y146.643 E0.06131
G1 X160.782 Y146.730 E0.06431
G1 X160.606 Y146.799 E0.06730
G1 X160.424 Y146.851 E0.07029
G1 X160.236 Y146.884 E0.07330
G1 X160.056 Y146.897 E0.07615
G1 X159.757 Y146.883 E0.08087
G1 X159.586 Y146.852 E0.08363
G1 X159.299 Y146.764 E0.08836
G1 X159.134 Y146.690 E0.09122
G1 X158.970 Y146.595 E0.09421
G1 X158.817 Y146.485 E0.09720
G1 X158.674 Y146.359 E0.10021
G1 X158.546 Y146.221 E0.10318
G1 X158.431 Y146.069 E0.10619
G1 X158.332 Y145.907 E0.10918
G1 X158.250 Y145.737 E0.11217
G1 X158.186 Y145.560 E0.11515
G1 X158.139 Y145.376 E0.11814
G1 X158.110 Y145.189 E0.12113
G1 X158.101 Y144.999 E0.12414
G1 X158.110 Y144.811 E0.12711
G1 X158.138 Y144.623 E0.13012
G1 X158.185 Y144.440 E0.13309
G1 X158.250 Y144.262 E0.13609
G1 X158.332 Y144.091 E0.13910
G1 X158.430 Y143.930 E0.14207
G1 X158.545 Y143.778 E0.14508
G1 X158.668 Y143.646 E0.14793
G1 X158.897 Y143.454 E0.15265
G1 X159.050 Y143.354 E0.15554
G1 X159.218 Y143.268 E0.15852
G1 X159.394 Y143.199 E0.16151
G1 X159.576 Y143.148 E0.16450
G1 X159.764 Y143.115 E0.16751
G1 X159.951 Y143.101 E0.17048
G1 X160.141 Y143.105 E0.17348
G1 X160.329 Y143.129 E0.17647
G1 X160.513 Y143.171 E0.17946
G1 X160.693 Y143.231 E0.18245
G1 X160.866 Y143.309 E0.18544
G1 X161.030 Y143.403 E0.18843
; feature outer perimeter
G1 X161.247 Y143.067 F18000
G92 E0.00000
G1 X161.433 Y143.200 E0.00362 F9554
G1 X161.603 Y143.350 E0.00720
G1 X161.834 Y143.612 E0.01271
G1 X161.962 Y143.799 E0.01630
G1 X162.071 Y144.000 E0.01992
G1 X162.161 Y144.212 E0.02354
G1 X162.228 Y144.431 E0.02716
G1 X162.274 Y144.655 E0.03078
G1 X162.297 Y144.883 E0.03441
G1 X162.297 Y145.113 E0.03803
G1 X162.274 Y145.342 E0.04167
G1 X162.229 Y145.567 E0.04529
G1 X162.161 Y145.785 E0.04889
G1 X162.072 Y145.996 E0.05252
G1 X161.963 Y146.197 E0.05614
G1 X161.834 Y146.387 E0.05976
G1 X161.687 Y146.563 E0.06338
G1 X161.523 Y146.723 E0.06700
G1 X161.342 Y146.867 E0.07064
G1 X161.151 Y146.990 E0.07425
G1 X160.947 Y147.095 E0.07787
G1 X160.734 Y147.179 E0.08149
G1 X160.513 Y147.241 E0.08511
G1 X160.286 Y147.281 E0.08875
G1 X160.061 Y147.298 E0.09232
G1 X159.713 Y147.281 E0.09783
G1 X159.492 Y147.242 E0.10137
G1 X159.158 Y147.139 E0.10690
G1 X158.952 Y147.046 E0.11046
G1 X158.753 Y146.932 E0.11408
G1 X158.567 Y146.798 E0.11770
G1 X158.394 Y146.646 E0.12135
G1 X158.239 Y146.478 E0.12495
G1 X158.100 Y146.295 E0.12859
G1 X157.980 Y146.099 E0.13221
G1 X157.881 Y145.893 E0.13583
G1 X157.803 Y145.678 E0.13944
G1 X157.746 Y145.456 E0.14306
G1 X157.712 Y145.229 E0.14668
G1 X157.700 Y144.999 E0.15032
G1 X157.712 Y144.771 E0.15392
G1 X157.746 Y144.543 E0.15757
G1 X157.802 Y144.322 E0.16117
G1 X157.880 Y144.107 E0.16479
G1 X157.980 Y143.899 E0.16843
G1 X158.099 Y143.705 E0.17203
G1 X158.238 Y143.521 E0.17568
G1 X158.392 Y143.356 E0.17924
G1 X158.659 Y143.131 E0.18475
G1 X158.850 Y143.008 E0.18835
G1 X159.053 Y142.904 E0.19195
G1 X159.266 Y142.820 E0.19558
G1 X159.487 Y142.757 E0.19920
G1 X159.714 Y142.717 E0.20284
G1 X159.941 Y142.700 E0.20644
G1 X160.171 Y142.706 E0.21006
G1 X160.398 Y142.734 E0.21369
G1 X160.622 Y142.785 E0.21731
G1 X160.839 Y142.858 E0.22093
G1 X161.048 Y142.952 E0.22455
G1 X161.247 Y143.067 E0.22817
G92 E0.00000
G1 E-0.50000 F2400
; feature solid layer
G1 X159.316 Y144.552 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X159.552 Y144.316 E0.00526 F9450
G1 X159.591 Y144.291 E0.00601
G1 X159.663 Y144.254 E0.00729
G1 X159.739 Y144.224 E0.00858
G1 X159.817 Y144.202 E0.00986
G1 X159.899 Y144.188 E0.01117
G1 X159.979 Y144.182 E0.01244
G1 X160.061 Y144.184 E0.01373
G1 X160.142 Y144.194 E0.01502
G1 X160.222 Y144.212 E0.01632
G1 X159.213 Y145.220 E0.03884
G1 X159.219 Y145.241 E0.03919
G1 X159.246 Y145.317 E0.04046
G1 X159.282 Y145.390 E0.04175
G1 X159.324 Y145.460 E0.04303
G1 X159.374 Y145.526 E0.04434
G1 X159.422 Y145.577 E0.04545
G1 X160.576 Y144.423 E0.07124
G1 X160.664 Y144.522 E0.07332
G1 X160.698 Y144.572 E0.07428
G1 X160.737 Y144.644 E0.07557
G1 X160.768 Y144.719 E0.07686
G1 X160.787 Y144.778 E0.07784
G1 X159.782 Y145.783 E0.10028
G1 X159.839 Y145.800 E0.10122
G1 X159.878 Y145.807 E0.10184
G1 X160.042 Y145.815 E0.10444
G1 X160.101 Y145.811 E0.10537
G1 X160.183 Y145.796 E0.10668
G1 X160.261 Y145.774 E0.10797
G1 X160.337 Y145.745 E0.10925
G1 X160.409 Y145.707 E0.11054
G1 X160.449 Y145.682 E0.11129
G1 X160.683 Y145.448 E0.11650
G92 E0.00000
G1 E-0.50000 F2400
; process Process 1
; feature inner perimeter
G1 X141.100 Y146.100 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X138.900 Y146.100 E0.03476 F10584
G1 X138.900 Y143.900 E0.06951
G1 X141.100 Y143.900 E0.10427
G1 X141.100 Y146.100 E0.13903
G1 X141.500 Y146.500 F18000
G92 E0.00000
G1 X138.500 Y146.500 E0.04740 F10584
G1 X138.500 Y143.500 E0.09479
G1 X141.500 Y143.500 E0.14219
G1 X141.500 Y146.500 E0.18958
G1 X141.900 Y146.900 F18000
G92 E0.00000
G1 X138.100 Y146.900 E0.06003 F11491
G1 X138.100 Y143.100 E0.12007
G1 X141.900 Y143.100 E0.18010
G1 X141.900 Y146.900 E0.24014
; feature outer perimeter
G1 X142.300 Y147.300 F18000
G92 E0.00000
G1 X137.700 Y147.300 E0.07267 F12172
G1 X137.700 Y142.700 E0.14535
G1 X142.300 Y142.700 E0.21802
G1 X142.300 Y147.300 E0.29069
G92 E0.00000
G1 E-0.50000 F2400
; feature solid layer
G1 X140.820 Y145.312 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X140.312 Y145.820 E0.01136 F9450
G1 X139.746 Y145.820 E0.02030
G1 X140.820 Y144.746 E0.04430
G1 X140.820 Y144.180 E0.05323
G1 X139.180 Y145.820 E0.08987
G1 X139.180 Y145.255 E0.09881
G1 X140.255 Y144.180 E0.12282
G1 X139.689 Y144.180 E0.13175
G1 X139.180 Y144.689 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 2
; feature inner perimeter
G1 X148.900 Y143.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y143.900 E0.03476 F10584
G1 X151.100 Y146.100 E0.06951
G1 X148.900 Y146.100 E0.10427
G1 X148.900 Y143.900 E0.13903
G1 X148.500 Y143.500 F18000
G92 E0.00000
G1 X151.500 Y143.500 E0.04740 F10584
G1 X151.500 Y146.500 E0.09479
G1 X148.500 Y146.500 E0.14219
G1 X148.500 Y143.500 E0.18958
G1 X148.100 Y143.100 F18000
G92 E0.00000
G1 X151.900 Y143.100 E0.06003 F11491
G1 X151.900 Y146.900 E0.12007
G1 X148.100 Y146.900 E0.18010
G1 X148.100 Y143.100 E0.24014
; feature outer perimeter
G1 X147.700 Y142.700 F18000
G92 E0.00000
G1 X152.300 Y142.700 E0.07267 F12172
G1 X152.300 Y147.300 E0.14535
G1 X147.700 Y147.300 E0.21802
G1 X147.700 Y142.700 E0.29069
G92 E0.00000
G1 E-0.50000 F2400
; feature solid layer
G1 X149.180 Y144.689 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X149.689 Y144.180 E0.01137 F9450
G1 X150.255 Y144.180 E0.02031
G1 X149.180 Y145.255 E0.04431
G1 X149.180 Y145.820 E0.05325
G1 X150.820 Y144.180 E0.08989
G1 X150.820 Y144.746 E0.09882
G1 X149.746 Y145.820 E0.12282
G1 X150.312 Y145.820 E0.13176
G1 X150.820 Y145.312 E0.14312
G92 E0.00000
G1 E-0.50000 F2400
; process Process 3
; feature inner perimeter
G1 X151.100 Y153.900 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X151.100 Y156.100 E0.03476 F15120
G1 X138.900 Y156.100 E0.22750
G1 X138.900 Y153.900 E0.26226
G1 X151.100 Y153.900 E0.45500
G1 X151.500 Y153.500 F18000
G92 E0.00000
G1 X151.500 Y156.500 E0.04740 F15120
G1 X138.500 Y156.500 E0.25278
G1 X138.500 Y153.500 E0.30017
G1 X151.500 Y153.500 E0.50555
G1 X151.900 Y153.100 F18000
G92 E0.00000
G1 X151.900 Y156.900 E0.06003 F15120
G1 X138.100 Y156.900 E0.27805
G1 X138.100 Y153.100 E0.33809
G1 X151.900 Y153.100 E0.55611
; feature outer perimeter
G1 X152.300 Y152.700 F18000
G92 E0.00000
G1 X152.300 Y157.300 E0.07267 F13230
G1 X137.700 Y157.300 E0.30333
G1 X137.700 Y152.700 E0.37601
G1 X152.300 Y152.700 E0.60666
G92 E0.00000
G1 E-0.50000 F2400
; feature solid layer
G1 X150.820 Y155.403 F18000
G92 E0.00000
G1 E0.50000 F2400
G92 E0.00000
G1 X150.403 Y155.820 E0.00932 F9450
G1 X149.837 Y155.820 E0.01826
G1 X150.820 Y154.837 E0.04022
G1 X150.820 Y154.271 E0.04916
G1 X149.271 Y155.820 E0.08376
G1 X148.706 Y155.820 E0.09270
G1 X150.346 Y154.180 E0.12934
G1 X149.780 Y154.180 E0.13828
G1 X148.140 Y155.820 E0.17492
G1 X147.574 Y155.820 E0.18385
G1 X149.214 Y154.180 E0.22050
G1 X148.649 Y154.180 E0.22943
G1 X147.009 Y155.820 E0.26608
G1 X146.443 Y155.820 E0.27501
G1 X148.083 Y154.180 E0.31165
G1 X147.517 Y154.180 E0.32059
G1 X145.877 Y155.820 E0.35723
G1 X145.312 Y155.820 E0.36617
G1 X146.952 Y154.180 E0.40281
G1 X146.386 Y154.180 E0.41175
G1 X144.746 Y155.820 E0.44839
G1 X144.180 Y155.820 E0.45733
G1 X145.820 Y154.180 E0.49397
G1 X145.255 Y154.180 E0.50291
G1 X143.615 Y155.820 E0.53955
G1 X143.049 Y155.820 E0.54848
G1 X144.689 Y154.180 E0.58513
G1 X144.123 Y154.180 E0.59406
G1 X142.483 Y155.820 E0.63071
G1 X141.917 Y155.820 E0.63964
G1 X143.557 Y154.180 E0.67628
G1 X142.992 Y154.180 E0.68522
G1 X141.352 Y155.820 E0.72186
G1 X140.786 Y155.820 E0.73080
G1 X142.426 Y154.180 E0.76744
G1 X141.860 Y154.180 E0.77638
G1 X140.220 Y155.820 E0.81302
G1 X139.655 Y155.820 E0.82196
G1 X141.295 Y154.180 E0.85860
G1 X140.729 Y154.180 E0.86754
G1 X139.180 Y155.729 E0.90215
G1 X139.180 Y155.163 E0.91108
G1 X140.163 Y154.180 E0.93305
G1 X139.598 Y154.180 E0.94199
G1 X139.180 Y154.598 E0.95132
G92 E0.00000
G1 E-0.50000 F2400
; layer end
END_PRINT
M106 S0 ; turn off cooling fan
; Build Summary
;   Build Time: 0 hours 3 minutes
;   Material Length: 291.4 mm (0.29 m)
;   Material Volume: 700.9 mm^3 (0.70 cc)
;   Material Weight: 0.88 g (0.00 lb)
;   Material Cost: 0.02
